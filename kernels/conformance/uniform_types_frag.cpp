// uniform_types_frag.cpp: twin of glsl/conformance/uniform_types.frag, line
// for line. Every uniform is read by its GL name (an array's elements, a
// struct array's members, the block's members as "Mixed.member"); a
// per-pixel index into an array picks each lane's element.
#include "kernels/conformance/conformance.h"

#include "shading/glsl_math.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs

// a[i] for each lane's i (0 <= i < N).
template <class T, size_t N, class Get> auto at(const std::array<T, N>& a, Int i, Get get) {
    auto r = get(a[0]);
    for (size_t k = 1; k < N; ++k) r = select(i == Int(int(k)), get(a[k]), r);
    return r;
}
}  // namespace

void UniformTypesFragment::bind(const Bindings& b) {
    palette_ = b.array<glm::vec3, 4>("palette");
    for (int k = 0; k < 2; ++k) {
        const std::string light = "lights[" + std::to_string(k) + "].";
        lights_[size_t(k)] = {b.get<glm::vec3>(light + "colour"), b.get<float>(light + "power"), b.get<int>(light + "kind"),
                              b.get<bool>(light + "on")};
    }
    count_ = b.get<int>("count");
    mask_ = b.get<uint32_t>("mask");
    flip_ = b.get<bool>("flip");
    axes_ = b.get<glm::bvec2>("axes");
    steps_ = b.get<glm::ivec3>("steps");
    bits_ = b.get<glm::uvec2>("bits");
    rot_ = b.get<glm::mat2>("rot");
    basis_ = b.get<glm::mat3>("basis");
    skew_ = b.get<glm::mat2x3>("skew");
    squash_ = b.get<glm::mat3x2>("squash");
    affine_ = b.get<glm::mat4x3>("affine");
    mixed_.a = b.get<float>("Mixed.a");
    mixed_.b = b.get<glm::vec3>("Mixed.b");
    mixed_.c = b.get<int>("Mixed.c");
    mixed_.d = b.get<glm::mat3>("Mixed.d");
    mixed_.e = b.get<bool>("Mixed.e");
    mixed_.f = b.get<glm::uvec2>("Mixed.f");
    mixed_.g = b.array<float, 3>("Mixed.g");
    mixed_.h = b.get<glm::mat2x3>("Mixed.h");
}

uint32_t UniformTypesFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

Vec4 UniformTypesFragment::main(const Fragment& frag) const {
    const Vec4 colour = frag.varying(v_colour);
    const Vec2 p = frag.varying(v_uv).xy();
    const Int cell = simd::itrunc(p.x * Float(12.0f));
    const Int i = cell & Int(3);
    const Int l = (cell >> 2) & Int(1);
    const auto vec3_of = [](const glm::vec3& v) { return Vec3(v); };
    // Every group's value (the GLSL's if-chain runs each under its mask),
    // then each lane's by its cell.
    const Vec4 r[12] = {
        Vec4(Vec3(palette_[1]), Float(1.0f)),
        Vec4(at(palette_, i, vec3_of), simd::to_float(i)),
        Vec4(at(lights_, l, [](const Light& x) { return Vec3(x.colour); }),
             at(lights_, l, [](const Light& x) { return Float(x.power); })),
        Vec4(at(lights_, l, [](const Light& x) { return Float(float(x.kind)); }),
             at(lights_, l, [](const Light& x) { return Float(x.on ? 1.0f : 0.0f); }), Float(float(count_)),
             Float(float(mask_ & 0xFFFFu))),
        Vec4(Mat2(rot_) * p, Float(axes_.x ? 1.0f : 0.0f), Float(axes_.y ? 1.0f : 0.0f)),
        Vec4(Mat3(basis_) * Vec3(p, colour.x), Float(float(steps_.y))),
        Vec4(Mat2x3(skew_) * p, (Mat3x2(squash_) * Vec3(p, colour.y)).x),
        Vec4(Mat4x3(affine_) * Vec4(p, colour.x, colour.y), Float(flip_ ? -1.0f : 1.0f)),
        Vec4(Vec3(mixed_.b), Float(mixed_.a)),
        Vec4(Mat3(mixed_.d) * Vec3(p, colour.z), Float(float(mixed_.c))),
        Vec4(Float(mixed_.e ? mixed_.g[1] : mixed_.g[2]), Float(float(mixed_.f.x & 0xFFFFu)),
             Float(float(mixed_.f.y >> 16)), Float(mixed_.g[0])),
        Vec4(Mat2x3(mixed_.h) * p, Float(float(bits_.x & 0xFFFFu)) + Float(float(steps_.z))),
    };
    Vec4 result = r[11];
    for (int k = 10; k >= 0; --k) result = select(cell == Int(k), r[k], result);
    return result * colour;
}

}  // namespace st
