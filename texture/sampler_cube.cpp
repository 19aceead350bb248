// sampler_cube.cpp: see sampler_cube.h. Section numbers are
// docs/llvmpipe/mipmaps-cubes-formats.md.
#include "texture/sampler_cube.h"

#include <cstring>

#include "simd/quad.h"
#include "texture/lod_selection.h"
#include "texture/texel_formats.h"
#include "texture/texel_math.h"

namespace st {

using namespace texel;

namespace {

constexpr int kFaces = 6;
constexpr int32_t kSign = int32_t(0x80000000u);

// v with its sign flipped where `negative` (the "±" of §5.2), exact.
ST_INLINE Float flip(Float v, Mask negative) {
    return simd::bit_cast_float(simd::bit_cast_int(v) ^ (select(negative, Int(kSign), Int(0))));
}
ST_INLINE Float neg(Float v) { return simd::bit_cast_float(simd::bit_cast_int(v) ^ Int(kSign)); }

// The face-coordinate table of §5.2 for a vector v on the lane's axis.
ST_INLINE void face_coords(const Vec3& v, Int axis, Mask negative, Float& sc, Float& tc) {
    const Mask x = axis == Int(0), y = axis == Int(1);
    sc = select(x, neg(flip(v.z, negative)), select(y, v.x, flip(v.x, negative)));
    tc = select(x, neg(v.y), select(y, flip(v.z, negative), neg(v.y)));
}

// Where a LINEAR tap that falls off a face lands (§5.5): per fall-off kind
// (x-, x+, y-, y+) and face, the new face and how x and y are made from
// the tap's other coordinate v: 0, max, v or max - v.
enum Pick : int32_t { kZero, kMax, kV, kMaxMinusV };
struct Remap {
    int32_t face[kFaces];
    Pick x[kFaces], y[kFaces];
};
constexpr Remap kXMinus = {{4, 5, 1, 1, 1, 0}, {kMax, kMax, kV, kMaxMinusV, kMax, kMax}, {kV, kV, kZero, kMax, kV, kV}};
constexpr Remap kXPlus = {{5, 4, 0, 0, 0, 1}, {kZero, kZero, kMaxMinusV, kV, kZero, kZero}, {kV, kV, kZero, kMax, kV, kV}};
constexpr Remap kYMinus = {{2, 2, 5, 4, 2, 2}, {kMax, kZero, kMaxMinusV, kV, kV, kMaxMinusV}, {kMaxMinusV, kV, kZero, kMax, kMax, kZero}};
constexpr Remap kYPlus = {{3, 3, 4, 5, 3, 3}, {kMax, kZero, kV, kMaxMinusV, kV, kMaxMinusV}, {kV, kMaxMinusV, kZero, kMax, kZero, kMax}};

// Lane-wise look-up of a 6-entry table by face.
ST_INLINE Int by_face(const int32_t (&table)[kFaces], Int face) {
    Int r(table[0]);
    for (int f = 1; f < kFaces; ++f) r = select(face == Int(f), Int(table[f]), r);
    return r;
}
ST_INLINE Int pick(const Pick (&table)[kFaces], Int face, Int v, Int max) {
    const Int p = by_face(reinterpret_cast<const int32_t(&)[kFaces]>(table), face);
    return select(p == Int(kZero), Int(0), select(p == Int(kMax), max, select(p == Int(kV), v, max - v)));
}

struct Tap {
    Int face, x, y;
};

ST_INLINE Tap remap(const Remap& r, Int face, Int v, Int max) {
    return {by_face(r.face, face), pick(r.x, face, v, max), pick(r.y, face, v, max)};
}

ST_INLINE Tap choose(Mask first, const Tap& a, Mask second, const Tap& b, const Tap& plain) {
    auto sel = [&](Int Tap::*m) { return select(first, a.*m, select(second, b.*m, plain.*m)); };
    return {sel(&Tap::face), sel(&Tap::x), sel(&Tap::y)};
}

}  // namespace

// A direction on its face: which face, the unprojected face coordinates
// and major axis, and the projected s', t' in [0, 1].
struct SamplerCube::Face {
    Int face, axis;
    Mask negative;
    Float sc, tc, ma, s, t;
};

SamplerCube::SamplerCube(const Texture& texture) : tex_(&texture) {
    last_level_ = int(texture.mips.size());
    mip_filter_ = last_level_ == 0 ? MipFilter::None : texture.mip_filter;
    lod_ = LodState::of(texture);
    aos_ = texture.format == TextureFormat::RGBA8 && texture.min_filter == TextureFilter::Nearest;
    size_t texels = 0;
    for (int l = 0; l <= last_level_; ++l) {
        const int w = l ? texture.mips[size_t(l - 1)].width : texture.width;
        level_size_.push_back(w);
        level_base_.push_back(int32_t(texels));
        texels += size_t(kFaces) * size_t(w) * size_t(w);
    }
    if (texture.format == TextureFormat::RGBA8) {
        rgba8_.assign(texels + kLanes, 0);
        for (int l = 0; l <= last_level_; ++l) {
            const auto& src = l ? texture.mips[size_t(l - 1)].texels8 : texture.texels8;
            std::memcpy(&rgba8_[size_t(level_base_[size_t(l)])], src.data(), src.size());
        }
    } else {
        rgba32_.assign(texels * 4, 0.0f);
        for (int l = 0; l <= last_level_; ++l) {
            const auto& src = l ? texture.mips[size_t(l - 1)].texels32 : texture.texels32;
            float* out = &rgba32_[size_t(level_base_[size_t(l)]) * 4];
            for (size_t i = 0; i < src.size() / 4; ++i) stored_texel(texture.format, &src[4 * i], out + 4 * i);
        }
    }
}

ST_INLINE SamplerCube::LevelLanes SamplerCube::level_lanes(Int level) const {
    // level is in [0, last_level_] on every lane.
    return {level_size_.lookup(level), level_base_.lookup(level)};
}

ST_INLINE Vec4 SamplerCube::texel(const LevelLanes& level, Int face, Int x, Int y) const {
    // Every tap is on its face by construction (clamped or remapped).
    const Int index = level.base + (face * level.size + y) * level.size + x;
    return gather_format_texels(tex_->format, rgba8_.data(), rgba32_.data(), index, Mask(true));
}

void SamplerCube::nearest_unorm8(const Face& f, Int level, Int& rb, Int& ga) const {
    const LevelLanes l = level_lanes(level);
    const Int size = l.size;
    const Float size_f = simd::to_float(size);
    const Int x = nearest_texel(f.s, size, size_f, true, TextureWrap::ClampToEdge);
    const Int y = nearest_texel(f.t, size, size_f, true, TextureWrap::ClampToEdge);
    const Int index = l.base + (f.face * size + y) * size + x;
    const Int t = simd::gather(rgba8_.data(), index, Mask(true));
    rb = red_blue(t);
    ga = green_alpha(t);
}

// One level's filter: NEAREST clamps to the face's edge (seamless filtering
// ignores NEAREST); LINEAR takes taps across the edges (§5.5) and, when a
// lane of the 8-lane vector has a corner, the weighted sum of §5.6.
Vec4 SamplerCube::filter_level(const Face& f, Int level_index) const {
    const LevelLanes level = level_lanes(level_index);
    const Int size = level.size;
    const Float size_f = simd::to_float(size);
    if (tex_->min_filter == TextureFilter::Nearest)
        return texel(level, f.face, nearest_texel(f.s, size, size_f, true, TextureWrap::ClampToEdge),
                     nearest_texel(f.t, size, size_f, true, TextureWrap::ClampToEdge));
    const Float u = maxps(f.s, Float(0.0f)) * size_f - Float(0.5f);
    const Float v = maxps(f.t, Float(0.0f)) * size_f - Float(0.5f);
    const Float u_floor = floor(u), v_floor = floor(v);
    const Float fx = u - u_floor, fy = v - v_floor;
    const Int x0 = itrunc(u_floor), y0 = itrunc(v_floor), x1 = x0 + Int(1), y1 = y0 + Int(1);
    const Int max = size - Int(1);
    const Mask x_minus = x0 < Int(0), x_plus = max < x1, y_minus = y0 < Int(0), y_plus = max < y1;
    const Int y0c = simd::max(y0, Int(0)), y1c = simd::min(y1, max);
    const Tap p00{f.face, x0, y0}, p01{f.face, x1, y0}, p10{f.face, x0, y1}, p11{f.face, x1, y1};
    const Tap a00 = choose(x_minus, remap(kXMinus, f.face, y0c, max), y_minus, remap(kYMinus, f.face, x0, max), p00);
    const Tap a01 = choose(x_plus, remap(kXPlus, f.face, y0c, max), y_minus, remap(kYMinus, f.face, x1, max), p01);
    const Tap a10 = choose(x_minus, remap(kXMinus, f.face, y1c, max), y_plus, remap(kYPlus, f.face, x0, max), p10);
    const Tap a11 = choose(x_plus, remap(kXPlus, f.face, y1c, max), y_plus, remap(kYPlus, f.face, x1, max), p11);
    const Vec4 t00 = texel(level, a00.face, a00.x, a00.y), t01 = texel(level, a01.face, a01.x, a01.y);
    const Vec4 t10 = texel(level, a10.face, a10.x, a10.y), t11 = texel(level, a11.face, a11.x, a11.y);

    const Mask corner = (x_minus || x_plus) && (y_minus || y_plus);
    const Mask corner_vectors = any_in_group(corner);
    Vec4 lerped(Float(0.0f)), summed(Float(0.0f));
    if (!all(corner_vectors)) {
        auto bilinear = [&](Float a00, Float a01, Float a10, Float a11) {
            return lerp_float(fy, lerp_float(fx, a00, a01), lerp_float(fx, a10, a11));
        };
        lerped = Vec4(bilinear(t00.x, t01.x, t10.x, t11.x), bilinear(t00.y, t01.y, t10.y, t11.y),
                      bilinear(t00.z, t01.z, t10.z, t11.z), bilinear(t00.w, t01.w, t10.w, t11.w));
    }
    if (any(corner_vectors)) {
        const Float wx0 = Float(1.0f) - fx, wy0 = Float(1.0f) - fy;
        Float w00 = wx0 * wy0, w01 = fx * wy0, w10 = wx0 * fy, w11 = fx * fy;
        // The corner tap fell off both axes; its weight goes to the other
        // three in thirds and it keeps none.
        const Mask c00 = corner && x_minus && y_minus, c01 = corner && x_plus && y_minus;
        const Mask c10 = corner && x_minus && y_plus, c11 = corner && x_plus && y_plus;
        Float c = select(c00, w00, select(c01, w01, select(c10, w10, select(c11, w11, Float(0.0f)))));
        c = c * Float(0x1.555556p-2f);
        w00 = select(c00, Float(0.0f), w00 + c);
        w01 = select(c01, Float(0.0f), w01 + c);
        w10 = select(c10, Float(0.0f), w10 + c);
        w11 = select(c11, Float(0.0f), w11 + c);
        auto sum = [&](Float a00, Float a01, Float a10, Float a11) {
            Float acc = w00 * a00;
            acc = w01 * a01 + acc;
            acc = w10 * a10 + acc;
            return w11 * a11 + acc;
        };
        summed = Vec4(sum(t00.x, t01.x, t10.x, t11.x), sum(t00.y, t01.y, t10.y, t11.y),
                      sum(t00.z, t01.z, t10.z, t11.z), sum(t00.w, t01.w, t10.w, t11.w));
    }
    return select(corner_vectors, summed, lerped);
}

Vec4 SamplerCube::sample_at(const Face& f, const LevelChoice& c) const {
    if (aos_) {
        Int rb0, ga0;
        nearest_unorm8(f, c.level0, rb0, ga0);
        const Int wl = level_weight8(c.fpart);
        if (c.two_levels && simd::any(wl != Int(0))) {
            Int rb1, ga1;
            nearest_unorm8(f, c.level1, rb1, ga1);
            blend_levels8(wl, rb0, ga0, rb1, ga1);
        }
        return unpack_pairs(rb0, ga0);
    }
    const Vec4 c0 = filter_level(f, c.level0);
    if (!c.two_levels) return c0;
    const Mask blend = any_in_group(!(c.fpart <= Float(0.0f)));
    if (none(blend)) return c0;
    // The second pass runs every lane of the vector at its own level1; a
    // magnified lane is back at level 0 there (choose_levels), and its taps
    // count for the vector's corner branch in filter_level (§5.6).
    return blend_levels(c.fpart, c0, filter_level(f, c.level1), blend);
}

namespace {

// Face selection (§5.1) and face coordinates (§5.2): z if |r| >= max(|s|,
// |t|), else x if |s| > |t|, else y, all unordered.
SamplerCube::Face select_face(const Vec3& d) {
    SamplerCube::Face f;
    const Float as = simd::abs(d.x), at = simd::abs(d.y), ar = simd::abs(d.z);
    const Mask xgt = !(as <= at);
    const Mask zge = !(ar < maxps(as, at));
    f.axis = select(zge, Int(2), select(xgt, Int(0), Int(1)));
    f.ma = select(zge, d.z, select(xgt, d.x, d.y));
    f.negative = simd::bit_cast_int(f.ma) < Int(0);
    f.face = f.axis + f.axis + select(f.negative, Int(1), Int(0));
    face_coords(d, f.axis, f.negative, f.sc, f.tc);
    return f;
}

}  // namespace

Vec4 SamplerCube::sample_lod(const Vec3& dir, Float lod) const {
    // Projection without derivatives (§5.3): k = 0.5 / |ma|, 0 for ma = 0.
    Face f = select_face(dir);
    const Float ama = simd::abs(f.ma);
    const Float k = select(!(ama <= Float(0.0f)), Float(0.5f) / ama, Float(0.0f));
    f.s = f.sc * k + Float(0.5f);
    f.t = f.tc * k + Float(0.5f);
    const bool needs_lod = mip_filter_ != MipFilter::None;
    if (!needs_lod) return sample_at(f, choose_levels(Float(0.0f), MipFilter::None, last_level_));
    return sample_at(f, choose_levels(lod_.requested(lod), mip_filter_, last_level_));
}

// Projection with derivatives (§5.3) and the per-pixel rho^2 of §5.4 from
// the direction's derivatives ddx, ddy, taken through the lane's face.
Float SamplerCube::project_rho2(const Vec3& dir, const Vec3& ddx, const Vec3& ddy, Face& f) const {
    f = select_face(dir);
    const Float ima = Float(1.0f) / f.ma;
    const Float ih = Float(0.5f) * ima;
    const Float k = simd::abs(ih);
    f.s = f.sc * k + Float(0.5f);
    f.t = f.tc * k + Float(0.5f);
    const Float w(float(tex_->width));
    auto rho_part = [&](const Vec3& dd) {
        const Mask x = f.axis == Int(0), y = f.axis == Int(1);
        const Float dma = select(x, dd.x, select(y, dd.y, dd.z));
        Float dsc, dtc;
        face_coords(dd, f.axis, f.negative, dsc, dtc);
        const Float q = dma * ima;
        Float a = (dsc - q * f.sc) * ih, b = (dtc - q * f.tc) * ih;
        a = w * a;
        b = w * b;
        return a * a + b * b;
    };
    const Float rho2 = maxps(rho_part(ddx), rho_part(ddy));
    const Mask special = (simd::bit_cast_int(rho2) & Int(0x7f800000)) == Int(0x7f800000);
    return select(special, Float(0.0f), rho2);
}

namespace {
Vec3 quad_ddx(const Vec3& v) { return {simd::quad_ddx(v.x), simd::quad_ddx(v.y), simd::quad_ddx(v.z)}; }
Vec3 quad_ddy(const Vec3& v) { return {simd::quad_ddy(v.x), simd::quad_ddy(v.y), simd::quad_ddy(v.z)}; }
}  // namespace

Vec4 SamplerCube::sample(const Vec3& dir) const {
    if (mip_filter_ == MipFilter::None) return sample_lod(dir, Float(0.0f));
    Face f;
    const Float rho2 = project_rho2(dir, quad_ddx(dir), quad_ddy(dir), f);
    return sample_at(f, choose_from_rho2(rho2, mip_filter_, last_level_, lod_));
}

Vec4 SamplerCube::sample_bias(const Vec3& dir, Float bias) const {
    if (mip_filter_ == MipFilter::None) return sample_lod(dir, Float(0.0f));
    Face f;
    const Float rho2 = project_rho2(dir, quad_ddx(dir), quad_ddy(dir), f);
    return sample_at(f, choose_levels(lod_.requested(half_fast_log2(rho2) + bias), mip_filter_, last_level_));
}

Vec4 SamplerCube::sample_grad(const Vec3& dir, const Vec3& dpdx, const Vec3& dpdy) const {
    if (mip_filter_ == MipFilter::None) return sample_lod(dir, Float(0.0f));
    Face f;
    const Float rho2 = project_rho2(dir, dpdx, dpdy, f);
    return sample_at(f, choose_from_rho2(rho2, mip_filter_, last_level_, lod_));
}

}  // namespace st
