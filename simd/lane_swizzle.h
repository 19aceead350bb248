// lane_swizzle.h: GLSL's swizzles as member functions of the lane vectors
// (lane_vec.h): `v.zyx()` reads where GLSL reads `v.zyx`, `c.rgb()` where it
// reads `c.rgb`, and `v.set_xz(u)` writes where GLSL writes `v.xz = u`.
// Every combination of two to four of a vector's components is declared, in
// the xyzw and the rgba names; a write with a repeated component (`set_xx`)
// is declared too but fails to compile where it is used, as GLSL refuses it.
//
// The preprocessor cannot nest a macro in itself, so each depth of the
// combination has its own copy of the component lists (A to D below).
#pragma once

// ST_SWZ_<depth>(M, S, N, ...) calls M(..., name, index) once for each of
// the first N components, named by S (xyzw or rgba).
#define ST_SWZ_A(M, S, N, ...) ST_SWZ_LIST_A(M, S, N, __VA_ARGS__)
#define ST_SWZ_B(M, S, N, ...) ST_SWZ_LIST_B(M, S, N, __VA_ARGS__)
#define ST_SWZ_C(M, S, N, ...) ST_SWZ_LIST_C(M, S, N, __VA_ARGS__)
#define ST_SWZ_D(M, S, N, ...) ST_SWZ_LIST_D(M, S, N, __VA_ARGS__)
#define ST_SWZ_LIST_A(M, S, N, ...) ST_SWZ_LIST_A2(M, ST_SWZ_NAMES_##S, N, __VA_ARGS__)
#define ST_SWZ_LIST_B(M, S, N, ...) ST_SWZ_LIST_B2(M, ST_SWZ_NAMES_##S, N, __VA_ARGS__)
#define ST_SWZ_LIST_C(M, S, N, ...) ST_SWZ_LIST_C2(M, ST_SWZ_NAMES_##S, N, __VA_ARGS__)
#define ST_SWZ_LIST_D(M, S, N, ...) ST_SWZ_LIST_D2(M, ST_SWZ_NAMES_##S, N, __VA_ARGS__)
#define ST_SWZ_LIST_A2(M, names, N, ...) ST_SWZ_EXPAND_A(M, names, N, __VA_ARGS__)
#define ST_SWZ_LIST_B2(M, names, N, ...) ST_SWZ_EXPAND_B(M, names, N, __VA_ARGS__)
#define ST_SWZ_LIST_C2(M, names, N, ...) ST_SWZ_EXPAND_C(M, names, N, __VA_ARGS__)
#define ST_SWZ_LIST_D2(M, names, N, ...) ST_SWZ_EXPAND_D(M, names, N, __VA_ARGS__)
#define ST_SWZ_EXPAND_A(M, x, y, z, w, N, ...) ST_SWZ_A_##N(M, x, y, z, w, __VA_ARGS__)
#define ST_SWZ_EXPAND_B(M, x, y, z, w, N, ...) ST_SWZ_B_##N(M, x, y, z, w, __VA_ARGS__)
#define ST_SWZ_EXPAND_C(M, x, y, z, w, N, ...) ST_SWZ_C_##N(M, x, y, z, w, __VA_ARGS__)
#define ST_SWZ_EXPAND_D(M, x, y, z, w, N, ...) ST_SWZ_D_##N(M, x, y, z, w, __VA_ARGS__)
#define ST_SWZ_NAMES_xyzw x, y, z, w
#define ST_SWZ_NAMES_rgba r, g, b, a

#define ST_SWZ_A_2(M, x, y, z, w, ...) M(__VA_ARGS__, x, 0) M(__VA_ARGS__, y, 1)
#define ST_SWZ_A_3(M, x, y, z, w, ...) ST_SWZ_A_2(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, z, 2)
#define ST_SWZ_A_4(M, x, y, z, w, ...) ST_SWZ_A_3(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, w, 3)
#define ST_SWZ_B_2(M, x, y, z, w, ...) M(__VA_ARGS__, x, 0) M(__VA_ARGS__, y, 1)
#define ST_SWZ_B_3(M, x, y, z, w, ...) ST_SWZ_B_2(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, z, 2)
#define ST_SWZ_B_4(M, x, y, z, w, ...) ST_SWZ_B_3(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, w, 3)
#define ST_SWZ_C_2(M, x, y, z, w, ...) M(__VA_ARGS__, x, 0) M(__VA_ARGS__, y, 1)
#define ST_SWZ_C_3(M, x, y, z, w, ...) ST_SWZ_C_2(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, z, 2)
#define ST_SWZ_C_4(M, x, y, z, w, ...) ST_SWZ_C_3(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, w, 3)
#define ST_SWZ_D_2(M, x, y, z, w, ...) M(__VA_ARGS__, x, 0) M(__VA_ARGS__, y, 1)
#define ST_SWZ_D_3(M, x, y, z, w, ...) ST_SWZ_D_2(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, z, 2)
#define ST_SWZ_D_4(M, x, y, z, w, ...) ST_SWZ_D_3(M, x, y, z, w, __VA_ARGS__) M(__VA_ARGS__, w, 3)

// Two components: reads a##b() and writes set_##a##b().
#define ST_SWZ2_MEMBER(S, N, a, ia, b, ib)                                                              \
    ST_INLINE LaneVec<T, 2> a##b() const { return {component<ia>(), component<ib>()}; }                 \
    ST_INLINE void set_##a##b(const LaneVec<T, 2>& v) { assign<ia, ib>(v); }
#define ST_SWZ2_SECOND(S, N, a, ia) ST_SWZ_B(ST_SWZ2_MEMBER, S, N, S, N, a, ia)
// Three.
#define ST_SWZ3_MEMBER(S, N, a, ia, b, ib, c, ic)                                                     \
    ST_INLINE LaneVec<T, 3> a##b##c() const { return {component<ia>(), component<ib>(), component<ic>()}; } \
    ST_INLINE void set_##a##b##c(const LaneVec<T, 3>& v) { assign<ia, ib, ic>(v); }
#define ST_SWZ3_THIRD(S, N, a, ia, b, ib) ST_SWZ_C(ST_SWZ3_MEMBER, S, N, S, N, a, ia, b, ib)
#define ST_SWZ3_SECOND(S, N, a, ia) ST_SWZ_B(ST_SWZ3_THIRD, S, N, S, N, a, ia)
// Four.
#define ST_SWZ4_MEMBER(S, N, a, ia, b, ib, c, ic, d, id)                                              \
    ST_INLINE LaneVec<T, 4> a##b##c##d() const {                                                      \
        return {component<ia>(), component<ib>(), component<ic>(), component<id>()};                  \
    }                                                                                                 \
    ST_INLINE void set_##a##b##c##d(const LaneVec<T, 4>& v) { assign<ia, ib, ic, id>(v); }
#define ST_SWZ4_FOURTH(S, N, a, ia, b, ib, c, ic) ST_SWZ_D(ST_SWZ4_MEMBER, S, N, S, N, a, ia, b, ib, c, ic)
#define ST_SWZ4_THIRD(S, N, a, ia, b, ib) ST_SWZ_C(ST_SWZ4_FOURTH, S, N, S, N, a, ia, b, ib)
#define ST_SWZ4_SECOND(S, N, a, ia) ST_SWZ_B(ST_SWZ4_THIRD, S, N, S, N, a, ia)

// Every swizzle of an N-component vector in the names S (xyzw or rgba).
#define ST_SWIZZLES_NAMED(S, N)                   \
    ST_SWZ_A(ST_SWZ2_SECOND, S, N, S, N)          \
    ST_SWZ_A(ST_SWZ3_SECOND, S, N, S, N)          \
    ST_SWZ_A(ST_SWZ4_SECOND, S, N, S, N)
#define ST_SWIZZLES(N) ST_SWIZZLES_NAMED(xyzw, N) ST_SWIZZLES_NAMED(rgba, N)
