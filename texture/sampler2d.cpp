// sampler2d.cpp: texture() and textureLod(), mirroring llvmpipe's two
// filtering paths, on all lanes at once (the scalar calls are one lane of
// the same code). Section numbers are docs/llvmpipe/mipmaps-cubes-formats.md.
//
// RGBA8 with REPEAT or CLAMP_TO_EDGE goes through the 8-bit fixed-point AoS
// sampler (gallivm lp_bld_sample_aos.c), everything else through the float
// SoA sampler (lp_bld_sample_soa.c) (§1.2). The level comes from the LOD
// selector (§2.4, §2.6); with a LINEAR mip filter two levels are filtered
// and blended, in float (SoA) or in 8 bits (AoS) (§2.8). Wraps follow §3,
// with the power-of-two choice made once from level 0. Integer lanes wrap
// modulo 2^32 and float-to-int conversions give INT32_MIN for NaN or
// out-of-range values, as on x86 (simd/lanes.h), so no coordinate is
// undefined behaviour; every texel read is bounds-checked or in range by
// construction.
#include "texture/sampler2d.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "texture/srgb_decode.h"
#include "texture/texel_formats.h"
#include "texture/lod_selection.h"
#include "texture/texel_math.h"
#include "texture/texel_window.h"

namespace st {

namespace {

using namespace texel;
using Level = Sampler2D::LevelLanes;

glm::vec4 lane0(const Vec4& v) { return glm::vec4(v.x[0], v.y[0], v.z[0], v.w[0]); }

}  // namespace

Sampler2D::Sampler2D(const Texture& texture) : tex_(&texture) {
    last_level_ = int(texture.mips.size());
    // A texture with one level has no mip filter (level_zero_only).
    mip_filter_ = last_level_ == 0 ? MipFilter::None : texture.mip_filter;
    lod_ = LodState::of(texture);
    shape_ = LodShape{texture.width, texture.height, last_level_, mip_filter_, lod_};
    pot_w_ = is_pot(texture.width);
    pot_h_ = is_pot(texture.height);
    auto simple_wrap = [](TextureWrap w) { return w == TextureWrap::Repeat || w == TextureWrap::ClampToEdge; };
    aos_ = texture.format == TextureFormat::RGBA8 && simple_wrap(texture.wrap_s) && simple_wrap(texture.wrap_t);
    clamped_bilinear_ = texture.format != TextureFormat::RGBA8 && !needs_lod() &&
                        texture.mag_filter == TextureFilter::Linear && texture.wrap_s == TextureWrap::ClampToEdge &&
                        texture.wrap_t == TextureWrap::ClampToEdge;

    size_t texels = 0;
    for (int l = 0; l <= last_level_; ++l) {
        const int w = l ? texture.mips[size_t(l - 1)].width : texture.width;
        const int h = l ? texture.mips[size_t(l - 1)].height : texture.height;
        level_width_.push_back(w);
        level_height_.push_back(h);
        level_base_.push_back(int32_t(texels));
        texels += size_t(w) * size_t(h);
    }
    load_texels(texels);
}

// Copies the texture's texels into the sampler's arrays, sized for
// `texels` texels of every level; arrays of that size already are reused
// as they stand (their padding stays zero).
void Sampler2D::load_texels(size_t texels, const std::vector<std::vector<float>>* float_levels) {
    const Texture& texture = *tex_;
    auto level_bytes = [&](int l) { return l ? texture.mips[size_t(l - 1)].texels8.data() : texture.texels8.data(); };
    auto level_floats = [&](int l) {
        if (float_levels) return (*float_levels)[size_t(l)].data();
        return l ? texture.mips[size_t(l - 1)].texels32.data() : texture.texels32.data();
    };
    if (texture.format == TextureFormat::RGBA8) {
        if (rgba8_.size() != texels + kLanes) rgba8_.assign(texels + kLanes, 0);
        for (int l = 0; l <= last_level_; ++l)
            std::memcpy(&rgba8_[size_t(level_base_[size_t(l)])], level_bytes(l),
                        size_t(level_width_[size_t(l)]) * size_t(level_height_[size_t(l)]) * 4);
        if (aos_ && needs_lod() && texture.min_filter == TextureFilter::Linear &&
            texture.mag_filter == TextureFilter::Linear)
            build_alpha_quads();
    } else if (texture.format == TextureFormat::SRGB8_ALPHA8) {
        // llvmpipe decodes each texel and takes the float path from there.
        if (rgba32_.size() != (texels + 1) * 4) rgba32_.assign((texels + 1) * 4, 0.0f);
        for (int l = 0; l <= last_level_; ++l) {
            const uint8_t* in = level_bytes(l);
            float* out = &rgba32_[size_t(level_base_[size_t(l)]) * 4];
            const size_t n = size_t(level_width_[size_t(l)]) * size_t(level_height_[size_t(l)]) * 4;
            for (size_t i = 0; i < n; ++i) out[i] = i % 4 == 3 ? srgb_texel_alpha(in[i]) : srgb_texel_colour(in[i]);
        }
    } else {
        // + 1: the right tap of row_pair's last pair
        if (rgba32_.size() != (texels + 1) * 4) rgba32_.assign((texels + 1) * 4, 0.0f);
        for (int l = 0; l <= last_level_; ++l) {
            const float* in = level_floats(l);
            float* out = &rgba32_[size_t(level_base_[size_t(l)]) * 4];
            const size_t n = size_t(level_width_[size_t(l)]) * size_t(level_height_[size_t(l)]);
            // RGBA32F stores texels as they are (render targets each frame).
            if (texture.format == TextureFormat::RGBA32F) std::memcpy(out, in, n * 4 * sizeof(float));
            else for (size_t i = 0; i < n; ++i) stored_texel(texture.format, in + 4 * i, out + 4 * i);
        }
    }
}

void Sampler2D::reload_texels(const std::vector<std::vector<float>>& levels) {
    const bool floats = tex_->format != TextureFormat::RGBA8 && tex_->format != TextureFormat::SRGB8_ALPHA8;
    if (!floats || levels.size() != level_width_.size())
        throw std::invalid_argument("reload_texels: a float texture's levels, one array each");
    for (size_t l = 0; l < levels.size(); ++l)
        if (levels[l].size() != size_t(level_width_[l]) * size_t(level_height_[l]) * 4)
            throw std::invalid_argument("reload_texels: level " + std::to_string(l) + " is not the texture's size");
    const size_t texels = size_t(level_base_.back()) + size_t(level_width_.back()) * size_t(level_height_.back());
    load_texels(texels, &levels);
}

// The right (or lower) neighbour of texel i on an axis of n texels, as
// linear_taps_fixed pairs the taps: wrapped for REPEAT, clamped for
// CLAMP_TO_EDGE.
static int neighbour(int i, int n, TextureWrap wrap) {
    if (wrap == TextureWrap::Repeat) return i + 1 == n ? 0 : i + 1;
    return std::min(i + 1, n - 1);
}

void Sampler2D::build_alpha_quads() {
    alpha_quads_.assign(rgba8_.size(), 0);
    auto alpha = [&](size_t i) { return uint32_t(rgba8_[i]) >> 24; };
    for (int l = 0; l <= last_level_; ++l) {
        const int w = level_width_[size_t(l)], h = level_height_[size_t(l)];
        const size_t base = size_t(level_base_[size_t(l)]);
        for (int y = 0; y < h; ++y) {
            const size_t row0 = base + size_t(y) * size_t(w);
            const size_t row1 = base + size_t(neighbour(y, h, tex_->wrap_t)) * size_t(w);
            for (int x = 0; x < w; ++x) {
                const size_t x1 = size_t(neighbour(x, w, tex_->wrap_s));
                const uint32_t q = alpha(row0 + size_t(x)) | alpha(row0 + x1) << 8 | alpha(row1 + size_t(x)) << 16 |
                                   alpha(row1 + x1) << 24;
                alpha_quads_[row0 + size_t(x)] = int32_t(q);
            }
        }
    }
}

ST_INLINE Sampler2D::LevelLanes Sampler2D::level_lanes(Int level) const {
    // level is in [0, last_level_] on every lane.
    LevelLanes l;
    l.width = level_width_.lookup(level);
    l.height = level_height_.lookup(level);
    l.base = level_base_.lookup(level);
    l.width_f = simd::to_float(l.width);
    l.height_f = simd::to_float(l.height);
    return l;
}

ST_INLINE Vec4 Sampler2D::texel(const LevelLanes& level, Int x, Int y, unsigned read) const {
    // Taps are inside their level by construction (wrapped or clamped, NaN
    // and infinite coordinates included); the mask only guards the texels.
    const Mask inside = !(x < Int(0)) && !(y < Int(0)) && x < level.width && y < level.height;
    return gather_texels(tex_->format == TextureFormat::RGBA8, rgba8_.data(), rgba32_.data(),
                         level.base + y * level.width + x, inside, read);
}

Vec4 Sampler2D::fetch(Int x, Int y, Int level) const {
    const Mask level_ok = !(level < Int(0)) && !(Int(last_level_) < level);
    const LevelLanes l = level_lanes(select(level_ok, level, Int(0)));
    const Mask inside = level_ok && !(x < Int(0)) && !(y < Int(0)) && x < l.width && y < l.height;
    const Int index = l.base + y * l.width + x;
    // Every lane reading one float texel (a table read in a loop, such as
    // the gather's sample pattern): one load of it for all.
    const int32_t first = index.v[0];
    if (tex_->format != TextureFormat::RGBA8 && all(inside && index == Int(first))) {
        const float* t = rgba32_.data() + size_t(first) * 4;
        return Vec4(Float(t[0]), Float(t[1]), Float(t[2]), Float(t[3]));
    }
    Vec4 r = gather_texels(tex_->format == TextureFormat::RGBA8, rgba8_.data(), rgba32_.data(), index, inside);
    if (tex_->format == TextureFormat::R32F) r.w = select(inside, r.w, Float(1.0f));  // the swizzle's 1
    return r;
}

glm::vec4 Sampler2D::fetch(int x, int y) const { return lane0(fetch(Int(x), Int(y))); }

glm::vec4 Sampler2D::sample(const glm::vec2& st) const {
    return lane0(sample_lod(Vec2(Float(st.x), Float(st.y)), Float(0.0f)));
}

// The two taps of row y, texels u.i0 and u.i1: one 8-float load per lane
// where they are neighbours (rgba32_ has a spare texel at its end), a
// gather for the lanes where the wrap or the clamp makes them otherwise.
ST_INLINE void Sampler2D::row_pair(const LevelLanes& level, const texel::LinearTaps& u, Int y, unsigned read,
                                   Vec4& left, Vec4& right) const {
    const Int row = level.base + y * level.width;
    Float f[8];
    simd::load_rows8(rgba32_.data(), (row + u.i0) * Int(4), f);
    left = Vec4(f[0], f[1], f[2], f[3]);
    right = Vec4(f[4], f[5], f[6], f[7]);
    const Mask apart = u.i1 != u.i0 + Int(1);
    if (any(apart))
        right = select(apart, gather_texels(false, nullptr, rgba32_.data(), row + u.i1, apart, read), right);
}

// The filter within one level, float SoA (§3.1).
ST_INLINE Vec4 Sampler2D::filter_float(const Vec2& st, const LevelLanes& level, TextureFilter filter,
                              Mask as_nearest, unsigned read) const {
    if (filter == TextureFilter::Nearest)
        return texel(level, nearest_texel(st.x, level.width, level.width_f, pot_w_, tex_->wrap_s),
                     nearest_texel(st.y, level.height, level.height_f, pot_h_, tex_->wrap_t), read);
    LinearTaps u = linear_taps_float(st.x, level.width, level.width_f, pot_w_, tex_->wrap_s);
    LinearTaps v = linear_taps_float(st.y, level.height, level.height_f, pot_h_, tex_->wrap_t);
    // Lanes that want NEAREST in a vector that filters linearly take the
    // bilinear code with each weight made 0 or 1: (w > 0.5 or NaN) ? 1 : 0
    // (lp_build_sample_image_linear with a linear mask, §2.7).
    if (any(as_nearest)) {
        auto snap = [&](Float w) { return select(as_nearest, select(!(w <= Float(0.5f)), Float(1.0f), Float(0.0f)), w); };
        u.weight = snap(u.weight);
        v.weight = snap(v.weight);
    }
    Vec4 t00, t10, t01, t11;
    // A texture one texel high (a table) has both rows in row 0 under every
    // wrap: the same taps, read once; the lerp between them stays.
    const bool one_row = tex_->height == 1;
    // Float texels are read as pairs: every wrap keeps every tap inside its
    // level, whatever the coordinate (linear_taps_float).
    if (tex_->format != TextureFormat::RGBA8) {
        row_pair(level, u, v.i0, read, t00, t10);
        if (one_row) t01 = t00, t11 = t10;
        else row_pair(level, u, v.i1, read, t01, t11);
    } else {
        t00 = texel(level, u.i0, v.i0, read), t10 = texel(level, u.i1, v.i0, read);
        t01 = one_row ? t00 : texel(level, u.i0, v.i1, read);
        t11 = one_row ? t10 : texel(level, u.i1, v.i1, read);
    }
    auto bilinear = [&](Float a00, Float a10, Float a01, Float a11) {
        return lerp_float(v.weight, lerp_float(u.weight, a00, a10), lerp_float(u.weight, a01, a11));
    };
    // Channels the caller does not read are 0, as gather_texels leaves them.
    auto channel = [&](unsigned c, Float a00, Float a10, Float a01, Float a11) __attribute__((always_inline)) {
        return (read >> c) & 1u ? bilinear(a00, a10, a01, a11) : Float(0.0f);
    };
    return Vec4(channel(0, t00.x, t10.x, t01.x, t11.x), channel(1, t00.y, t10.y, t01.y, t11.y),
                channel(2, t00.z, t10.z, t01.z, t11.z), channel(3, t00.w, t10.w, t01.w, t11.w));
}

// The filter within one level, 8-bit AoS (§3.2): the result as byte pairs,
// rb = R | B << 16 and ga = G | A << 16, before conversion to float. When
// every lane reads one level (level0 says it is level 0) the texel windows
// replace the gathers.
// Its helpers and lambdas are forced inline: out of line, their vectors go
// through memory, which cost 40 % of the unscaled RGBA8 rate (microbench).
ST_INLINE void Sampler2D::filter_unorm8(const Vec2& st, const LevelLanes& lanes_level, TextureFilter filter,
                                        bool level0, unsigned read, Mask active, Int& rb, Int& ga) const {
    const int32_t* texels = rgba8_.data();
    if (filter == TextureFilter::Nearest) {
        const LevelLanes& level = lanes_level;
        const Int x = nearest_texel(st.x, level.width, level.width_f, pot_w_, tex_->wrap_s);
        const Int y = nearest_texel(st.y, level.height, level.height_f, pot_h_, tex_->wrap_t);
        const Int t = simd::gather(texels, level.base + y * level.width + x, active);
        rb = red_blue(t);
        ga = green_alpha(t);
        return;
    }
    LevelLanes level = lanes_level;
    LinearTaps8 u = linear_taps_fixed(st.x, level.width, level.width_f, pot_w_, tex_->wrap_s);
    LinearTaps8 v = linear_taps_fixed(st.y, level.height, level.height_f, pot_h_, tex_->wrap_t);
    // Lanes outside `active` (their results are not used) read where a
    // lead lane reads, level and taps, so that they neither break a texel
    // window nor take a gather of their own; their weights stay theirs.
    if (!all(active)) {
        const Int lead = lead_lanes(active);
        auto follow = [&](Int x) __attribute__((always_inline)) { return select(active, x, simd::permute(x, lead)); };
        u.i0 = follow(u.i0), u.i1 = follow(u.i1), v.i0 = follow(v.i0), v.i1 = follow(v.i1);
        level.base = follow(level.base), level.width = follow(level.width), level.height = follow(level.height);
    }
    // All lanes on one level (level 0 without mips, or a LOD that changes
    // slowly across the call): that level's rows can be windowed.
    const int32_t base0 = level.base[0];
    const bool one_level = level0 || all(level.base == Int(base0));
    // Every lane that counts at a texel centre, to within the 8-bit weights
    // (a texture drawn texel for texel: a background, a full-screen pass):
    // both weights are 0, and lerp8 with weight 0 returns its first
    // operand as it is, so the lower-left tap alone is the result.
    if (!simd::any_bit(select(active, u.weight | v.weight, Int(0)))) {
        Int t;
#if defined(ST_SIMD_AVX512)
        const bool windowed = one_level && fetch_window_groups_centre(texels + base0, level.width[0], level.height[0], u, v, t);
#else
        const bool windowed = one_level && fetch_window_group_centre(texels + base0, level.width[0], level.height[0], u, v, t);
#endif
        if (!windowed) t = simd::gather(texels, level.base + v.i0 * level.width + u.i0, Mask(true));
        rb = read & kReadRedBlue ? red_blue(t) : Int(0);
        ga = read & kReadGreenAlpha ? green_alpha(t) : Int(0);
        return;
    }
    // Each row's two taps are neighbours but where the wrap or the clamp
    // joins them otherwise; those lanes are fetched again.
    Int t00, t10, t01, t11;
    bool windowed = false;
    if (one_level) {
        const int32_t* rows = texels + base0;
        const int w = level.width[0];
#if defined(ST_SIMD_AVX512)
        windowed = fetch_window_groups_2rows(rows, w, level.height[0], u, v, t00, t10, t01, t11) ||
                   fetch_window_groups_4rows(rows, w, level.height[0], u, v, t00, t10, t01, t11) ||
                   fetch_window(rows, w, u, v, t00, t10, t01, t11);
#else
        windowed = fetch_window_group_2rows(rows, w, level.height[0], u, v, t00, t10, t01, t11) ||
                   fetch_window_group_4rows(rows, w, level.height[0], u, v, t00, t10, t01, t11) ||
                   fetch_window(rows, w, u, v, t00, t10, t01, t11);
#endif
    }
    if (!windowed) {
        const Int row0 = level.base + v.i0 * level.width, row1 = level.base + v.i1 * level.width;
        simd::gather_pairs(texels, row0 + u.i0, t00, t10);
        simd::gather_pairs(texels, row1 + u.i0, t01, t11);
        const Mask apart = u.i1 != u.i0 + Int(1);
        if (simd::any(apart)) {
            t10 = select(apart, simd::gather(texels, row0 + u.i1, apart), t10);
            t11 = select(apart, simd::gather(texels, row1 + u.i1, apart), t11);
        }
    }
    // Two channels per lane, one in each 16-bit half (R and B, then G and
    // A), lerped at once.
    const Int wu = lerp8_weight(u.weight), wv = lerp8_weight(v.weight);
    // Inlined by hand (a lambda here stays out of line and spills its
    // vectors): R and B with shift 0, G and A with shift 8.
    auto pairs = [&](int shift) __attribute__((always_inline)) {
        auto half_bytes = [shift](Int t) __attribute__((always_inline)) { return shift ? green_alpha(t) : red_blue(t); };
        const Int bottom = lerp8_pairs(wu, half_bytes(t00), half_bytes(t10));
        const Int top = lerp8_pairs(wu, half_bytes(t01), half_bytes(t11));
        return lerp8_pairs(wv, bottom, top);
    };
    // A pair no channel of `read` is in is not filtered (0).
    rb = read & kReadRedBlue ? pairs(0) : Int(0);
    ga = read & kReadGreenAlpha ? pairs(8) : Int(0);
}

// min == mag: the one filter at the chosen levels.
Vec4 Sampler2D::filter_levels(const Vec2& st, const LevelChoice& c, TextureFilter filter, bool aos, unsigned read,
                               Mask active) const {
    const LevelLanes l0 = level_lanes(c.level0);
    if (aos) {
        Int rb0, ga0;
        filter_unorm8(st, l0, filter, false, read, active, rb0, ga0);
        const Int wl = level_weight8(c.fpart);
        // Each lane is its own here: the second level only where an
        // active lane weighs it.
        if (c.two_levels && simd::any(active && wl != Int(0))) {
            Int rb1, ga1;
            filter_unorm8(st, level_lanes(c.level1), filter, false, read, active, rb1, ga1);
            blend_levels8(wl, rb0, ga0, rb1, ga1, read);
        }
        return unpack_pairs(rb0, ga0, read);
    }
    const Vec4 c0 = filter_float(st, l0, filter, Mask(false), read);
    if (!c.two_levels) return c0;
    // The second level only where some lane of the 8-lane vector has a
    // weight (unordered: NaN counts); elsewhere C0 as it is (§2.8).
    return blend_second_level(st, c, filter, Mask(false), any_in_group(!(c.fpart <= Float(0.0f))), c0, read);
}

// C0 blended with level1's result in the lanes of `blend`:
// fmuladd(max(fpart, 0), C1 - C0, C0).
Vec4 Sampler2D::blend_second_level(const Vec2& st, const LevelChoice& c, TextureFilter filter, Mask as_nearest,
                                   Mask blend, const Vec4& c0, unsigned read) const {
    if (none(blend)) return c0;
    return blend_levels(c.fpart, c0, filter_float(st, level_lanes(c.level1), filter, as_nearest, read), blend);
}

Vec4 Sampler2D::sample_levels(const Vec2& st, const LevelChoice& c, bool per_quad_lod, unsigned read,
                              Mask active) const {
    const TextureFilter min = tex_->min_filter, mag = tex_->mag_filter;
    // RGBA8 stays on the 8-bit path unless min != mag with a LOD per lane (§1.2).
    const bool aos = aos_ && (min == mag || per_quad_lod);
    if (min == mag) return filter_levels(st, c, min, aos, read, active);
    if (aos) {
        // Per quad: minified quads take the min filter at their levels, the
        // others the mag filter at the base, without mip filtering.
        LevelChoice base;
        base.level0 = base.level1 = Int(0);
        base.fpart = Float(0.0f);
        const Vec4 minified = filter_levels(st, c, min, true, read, active);
        const Vec4 magnified = filter_levels(st, base, mag, true, read, active);
        return select(c.minified, minified, magnified);
    }
    // SoA decides per 8-lane vector: with no lane needing LINEAR, true
    // NEAREST (with the mip filter when min is NEAREST); otherwise every lane
    // filters linearly, the NEAREST ones with snapped weights, and with a
    // LINEAR mip filter the second level blends where a lane is minified.
    const Mask needs_linear = min == TextureFilter::Linear ? c.minified : !c.minified;
    const Mask linear_vectors = any_in_group(needs_linear);
    Vec4 nearest(Float(0.0f)), linear(Float(0.0f));
    if (!all(linear_vectors)) {
        if (min == TextureFilter::Nearest) {
            nearest = filter_levels(st, c, TextureFilter::Nearest, false, read, Mask(true));
        } else {
            nearest = filter_float(st, level_lanes(Int(0)), TextureFilter::Nearest, Mask(false), read);
        }
    }
    if (any(linear_vectors)) {
        const Mask as_nearest = !needs_linear;
        linear = filter_float(st, level_lanes(c.level0), TextureFilter::Linear, as_nearest, read);
        if (c.two_levels)
            linear = blend_second_level(st, c, TextureFilter::Linear, as_nearest,
                                        linear_vectors && any_in_group(c.minified), linear, read);
    }
    return select(linear_vectors, linear, nearest);
}

ST_INLINE bool Sampler2D::needs_lod() const {
    return mip_filter_ != MipFilter::None || tex_->min_filter != tex_->mag_filter;
}

// One level, one filter: no LOD at all, whatever the op (§1.1).
ST_INLINE Vec4 Sampler2D::sample_base(const Vec2& st, unsigned read, Mask active) const {
    const LevelLanes l0 = level_lanes(Int(0));
    if (!aos_) return filter_float(st, l0, tex_->mag_filter, Mask(false), read);
    Int rb, ga;
    filter_unorm8(st, l0, tex_->mag_filter, true, read, active, rb, ga);
    return unpack_pairs(rb, ga, read);
}

// rho^2 per quad from its top-left lane's differences, at the base level's
// size; every op rounded on its own (§2.2).
Float Sampler2D::quad_rho2(const Vec2& st) const {
    const Float w(float(tex_->width)), h(float(tex_->height));
    const Float s_tl = simd::shuffle(st.x, kQuadTL), t_tl = simd::shuffle(st.y, kQuadTL);
    const Float dsdx = simd::shuffle(st.x, kQuadTR) - s_tl, dtdx = simd::shuffle(st.y, kQuadTR) - t_tl;
    const Float dsdy = simd::shuffle(st.x, kQuadBL) - s_tl, dtdy = simd::shuffle(st.y, kQuadBL) - t_tl;
    Float a = dsdx * w, c = dtdx * h, b = dsdy * w, d = dtdy * h;
    a = a * a, b = b * b, c = c * c, d = d * d;
    return maxps(a + c, b + d);
}

Vec4 Sampler2D::sample(const Vec2& st, unsigned read, Mask active) const {
    // No lane uses the result (a loop's last pass, after its last lane
    // left): nothing to read.
    if (none(active)) return Vec4(Float(0.0f));
    if (!needs_lod()) return sample_base(st, read, active);
    return sample_levels(st, choose_from_rho2(quad_rho2(st), mip_filter_, last_level_, lod_), true, read, active);
}

Sampler2D::ImplicitLevels Sampler2D::implicit_levels(const Vec2& st) const {
    // Chosen even where this sampler needs no LOD: a sampler of the same
    // shape with min != mag does.
    return ImplicitLevels{choose_from_rho2(quad_rho2(st), mip_filter_, last_level_, lod_), shape_};
}

Vec4 Sampler2D::sample(const Vec2& st, const ImplicitLevels& levels, unsigned read, Mask active) const {
    if (!(levels.shape == shape_)) return sample(st, read, active);
    if (none(active)) return Vec4(Float(0.0f));
    if (!needs_lod()) return sample_base(st, read, active);
    return sample_levels(st, levels.choice, true, read, active);
}

Vec4 Sampler2D::sample_bias(const Vec2& st, Float bias) const {
    if (!needs_lod()) return sample_base(st);
    // The quad's LOD plus each lane's bias: no shortcut (§2.4 step 3).
    return sample_levels(st, choose_levels(lod_.requested(half_fast_log2(quad_rho2(st)) + bias), mip_filter_, last_level_), false);
}

Vec4 Sampler2D::sample_lod_levels(const Vec2& st, Float lod, unsigned read) const {
    if (!needs_lod()) return sample_base(st, read);
    return sample_levels(st, choose_levels(lod_.requested(lod), mip_filter_, last_level_), false, read);
}

texel::LevelChoice Sampler2D::grad_levels(const Vec2& dx, const Vec2& dy) const {
    if (!needs_lod()) return texel::LevelChoice{};  // unused: sample_grad samples the base level
    // Per lane, each product, square and sum rounded, and an infinite or
    // NaN rho^2 taken as 0 (§2.3).
    const Float w(float(tex_->width)), h(float(tex_->height));
    Float a = w * dx.x, c = h * dx.y, b = w * dy.x, d = h * dy.y;
    a = a * a, b = b * b, c = c * c, d = d * d;
    Float rho2 = maxps(a + c, b + d);
    const Mask special = (simd::bit_cast_int(rho2) & Int(0x7f800000)) == Int(0x7f800000);
    rho2 = select(special, Float(0.0f), rho2);
    return choose_from_rho2(rho2, mip_filter_, last_level_, lod_);
}

Vec4 Sampler2D::sample_grad(const Vec2& st, const texel::LevelChoice& levels) const {
    if (!needs_lod()) return sample_base(st);
    return sample_levels(st, levels, false);
}

// filter_unorm8's bilinear alpha from the footprint quads: the same taps
// and the same 8-bit lerps (each 16-bit half of lerp8_pairs is on its own),
// with the two rows' horizontal lerps in one call. A CLAMP_TO_EDGE tap pair
// left of the edge (both taps texel 0) is no quad; those lanes assemble
// theirs from the texels.
ST_INLINE Int Sampler2D::alpha_bilinear(const Vec2& st, const LevelLanes& level) const {
    const LinearTaps8 u = linear_taps_fixed(st.x, level.width, level.width_f, pot_w_, tex_->wrap_s);
    const LinearTaps8 v = linear_taps_fixed(st.y, level.height, level.height_f, pot_h_, tex_->wrap_t);
    const Int row0 = level.base + v.i0 * level.width;
    Int q = simd::gather(alpha_quads_.data(), row0 + u.i0, Mask(true));
    Mask loose(false);
    if (tex_->wrap_s == TextureWrap::ClampToEdge) loose = loose || (u.i1 == u.i0 && u.i0 != level.width - Int(1));
    if (tex_->wrap_t == TextureWrap::ClampToEdge) loose = loose || (v.i1 == v.i0 && v.i0 != level.height - Int(1));
    if (any(loose)) {
        const Int row1 = level.base + v.i1 * level.width;
        auto a = [&](Int index) __attribute__((always_inline)) {
            return (simd::gather(rgba8_.data(), index, loose) >> 24) & Int(0xff);
        };
        const Int own = a(row0 + u.i0) | a(row0 + u.i1) << 8 | a(row1 + u.i0) << 16 | a(row1 + u.i1) << 24;
        q = select(loose, own, q);
    }
    // [a00 | a01 << 16] against [a10 | a11 << 16]: the lower row in the low
    // half, the upper in the high one.
    const Int rows = lerp8_pairs(lerp8_weight(u.weight), q & Int(0x00ff00ff), (q >> 8) & Int(0x00ff00ff));
    return lerp8_pairs(lerp8_weight(v.weight), rows & Int(0xff), (rows >> 16) & Int(0xff));
}

Float Sampler2D::sample_grad_alpha(const Vec2& st, const texel::LevelChoice& c) const {
    // Only mip-mapped bilinear RGBA8 has quads (the constructor decides).
    if (alpha_quads_.empty()) return sample_grad(st, c).w;
    Int a = alpha_bilinear(st, level_lanes(c.level0));
    if (c.two_levels) {
        a = lerp8_pairs(lerp8_weight(level_weight8(c.fpart)), a, alpha_bilinear(st, level_lanes(c.level1)));
    }
    return unorm8_to_float(a);
}

Vec4 Sampler2D::sample_grad(const Vec2& st, const Vec2& dx, const Vec2& dy) const {
    return sample_grad(st, grad_levels(dx, dy));
}

Int Sampler2D::size_x(Int lod) const { return texture_size(lod, true); }
Int Sampler2D::size_y(Int lod) const { return texture_size(lod, false); }

// textureSize: the lod of lane 0 of each 8-lane vector for the whole
// vector; 0 outside [0, last level] (§6).
Int Sampler2D::texture_size(Int lod, bool x) const {
    Int out(0);
    for (int g = 0; g < kLanes / 8; ++g) {
        const int level = lod[8 * g];
        const int size = level < 0 || level > last_level_ ? 0
                         : x                              ? level_width_[size_t(level)]
                                                          : level_height_[size_t(level)];
        out = select(Mask::from_bits(0xffu << (8 * g)), Int(size), out);
    }
    return out;
}

}  // namespace st
