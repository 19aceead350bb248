// lod_selection.h: from a LOD (explicit, or log2 rho) to the levels a
// sample reads, their weights and whether it is minified: llvmpipe's LOD
// selector in GL's default sampler state (no sampler bias, MIN_LOD 0,
// MAX_LOD 1000) and its level selection (docs/llvmpipe/
// mipmaps-cubes-formats.md §2.4-§2.7). Shared by both samplers.
#pragma once

#include "frame/frame.h"
#include "simd/lane_vec.h"
#include "texture/lod_state.h"
#include "texture/texel_math.h"

namespace st::texel {


// The levels one sample reads and how it weighs them (§2.6), and whether
// it is minified (§2.7).
struct LevelChoice {
    Int level0, level1;
    Float fpart;  // weight of level1; 0 where only level0 counts
    Mask minified;
    bool two_levels = false;
};

// What the levels of an implicit LOD depend on besides the coordinate:
// two textures alike in all of it choose the same levels at one point.
struct LodShape {
    int width = 0, height = 0, last_level = 0;
    MipFilter mip_filter = MipFilter::None;
    LodState state;
    bool operator==(const LodShape&) const = default;
};

// The LOD selector (§2.4) and level selection (§2.6) for min == mag, GL's
// default sampler state (no bias, MIN_LOD 0, MAX_LOD 1000). `lod` is
// log2(rho) for an implicit LOD (the caller has applied 0.5 * fast_log2 or
// the shortcut) or the shader's value for textureLod.
inline LevelChoice choose_levels(Float lod, MipFilter mip_filter, int last_level) {
    LevelChoice c;
    const Int last(last_level);
    c.minified = !(lod <= Float(0.0f));  // unordered: a NaN LOD minifies
    if (mip_filter == MipFilter::None) {
        c.level0 = c.level1 = Int(0);
        c.fpart = Float(0.0f);
    } else if (mip_filter == MipFilter::Linear) {
        const Float fl = floor(lod);
        Float fpart = lod - fl;
        Int l0 = itrunc(fl), l1 = l0 + Int(1);
        // Below the base or at or past the last level only one level counts,
        // and *both* levels become that one (§2.6): a magnified lane reads
        // level 0 in the second pass too, not level 1. Its weight is 0, but
        // which texels it reads there still matters: to the other lanes of
        // its 8-lane vector, through whether one of them has a seamless cube
        // corner (§5.6), and to itself when a texel there is infinite
        // (0 * inf is NaN).
        const Mask below = l0 < Int(0);
        l0 = select(below, Int(0), l0);
        l1 = select(below, Int(0), l1);
        fpart = select(below, Float(0.0f), fpart);
        const Mask top = !(l0 < last);
        l0 = select(top, last, l0);
        l1 = select(top, last, l1);
        fpart = select(top, Float(0.0f), fpart);
        c.level0 = l0;
        c.level1 = l1;
        c.fpart = fpart;
        c.two_levels = true;
    } else {
        c.level0 = c.level1 = simd::clamp(iround(lod), Int(0), last);
        c.fpart = Float(0.0f);
    }
    return c;
}

// The selector for rho^2 without a shader bias (texture(), textureGrad):
// GL's default state takes the exponent shortcut for NEAREST and NONE mip
// filters, round_half_up(log2 rho), and minifies where rho^2 > 1
// (unordered); LINEAR goes through 0.5 * fast_log2 (§2.4).
inline LevelChoice choose_from_rho2(Float rho2, MipFilter mip_filter, int last_level, const LodState& state) {
    if (state.equal) return choose_levels(Float(state.min_lod), mip_filter, last_level);
    if (mip_filter == MipFilter::Linear || !state.plain())
        return choose_levels(state.adjust(half_fast_log2(rho2)), mip_filter, last_level);
    LevelChoice c;
    const Int exponent = (simd::bit_cast_int(rho2) >> 23) & Int(255);
    const Int ipart = (exponent - Int(126)) >> 1;
    c.level0 = c.level1 = mip_filter == MipFilter::None ? Int(0) : simd::clamp(ipart, Int(0), Int(last_level));
    c.fpart = Float(0.0f);
    c.minified = !(rho2 <= Float(1.0f));
    return c;
}

}  // namespace st::texel
