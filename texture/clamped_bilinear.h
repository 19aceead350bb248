// clamped_bilinear.h: the float SoA bilinear filter (sampler2d.cpp's
// filter_float, §3.1 of docs/llvmpipe/mipmaps-cubes-formats.md) for the
// case a gather loop spends its time in: one level, LINEAR, CLAMP_TO_EDGE
// on both axes, inlined into the twin so that the channels it reads and a
// table's single row fold away, with the taps found once for every texture
// of one shape read at the same point (texture/bilinear_taps.h). The
// arithmetic is filter_float's, op for op: the same bits (every golden
// hash; Sampler2D.BilinearTaps* in sampler2d_test.cpp).
// Included at the end of sampler2d.h, not on its own.
#pragma once

#include "texture/texel_math.h"

namespace st {

ST_INLINE BilinearTaps Sampler2D::bilinear_taps(const Vec2& st) const {
    BilinearTaps t;
    t.st = st;
    if (!clamped_bilinear_) return t;
    const int w = tex_->width, h = tex_->height;
    t.width = w, t.height = h;
    const texel::LinearTaps u = texel::linear_taps_float(st.x, Int(w), Float(float(w)), pot_w_, TextureWrap::ClampToEdge);
    const texel::LinearTaps v = texel::linear_taps_float(st.y, Int(h), Float(float(h)), pot_h_, TextureWrap::ClampToEdge);
    // Under CLAMP_TO_EDGE every tap is inside (a NaN coordinate clamps to
    // the last texel), and the right tap is the left one's neighbour except
    // at the last column, where it is the left tap itself. The pair's load
    // there reads the next row's first texel (or rgba32_'s spare one), which
    // the filter drops.
    t.at_last_column = u.i1 == u.i0;
    t.row0 = simd::LaneOffsets((v.i0 * Int(w) + u.i0) * Int(4));
    if (h > 1) t.row1 = simd::LaneOffsets((v.i1 * Int(w) + u.i0) * Int(4));
    t.wu = u.weight, t.wv = v.weight;
    return t;
}

ST_INLINE Vec4 Sampler2D::sample_lod(const BilinearTaps& taps, unsigned read) const {
    if (!clamped_bilinear_ || taps.width != tex_->width || taps.height != tex_->height)
        return sample_lod_levels(taps.st, Float(0.0f), read);
    auto row = [&](const simd::LaneOffsets& at, Vec4& left, Vec4& right) __attribute__((always_inline)) {
        Float f[8];
        simd::load_rows8(rgba32_.data(), at, f);
        left = Vec4(f[0], f[1], f[2], f[3]);
        right = select(taps.at_last_column, left, Vec4(f[4], f[5], f[6], f[7]));
    };
    Vec4 t00, t10, t01, t11;
    row(taps.row0, t00, t10);
    // A texture one texel high (a table): both rows are row 0, read once;
    // the lerp between them stays, as in filter_float.
    if (taps.height == 1) t01 = t00, t11 = t10;
    else row(taps.row1, t01, t11);
    // Channels the caller does not read are 0, as gather_texels leaves them.
    auto channel = [&](unsigned c, Float a00, Float a10, Float a01, Float a11) __attribute__((always_inline)) {
        if (!((read >> c) & 1u)) return Float(0.0f);
        return texel::lerp_float(taps.wv, texel::lerp_float(taps.wu, a00, a10), texel::lerp_float(taps.wu, a01, a11));
    };
    return Vec4(channel(0, t00.x, t10.x, t01.x, t11.x), channel(1, t00.y, t10.y, t01.y, t11.y),
                channel(2, t00.z, t10.z, t01.z, t11.z), channel(3, t00.w, t10.w, t01.w, t11.w));
}

}  // namespace st
