// lod_state.h: the GL sampler state that shapes the LOD (bias, MIN_LOD,
// MAX_LOD), as llvmpipe bakes it into its LOD selector
// (docs/llvmpipe/mipmaps-cubes-formats.md §2.1, §2.4).
#pragma once

#include <algorithm>
#include <cmath>

#include "frame/frame.h"
#include "simd/lane_vec.h"

namespace st::texel {

// The sampler state llvmpipe bakes into the selector (§2.1), only where
// there is a mip filter or min != mag: the bias quantized to 1/256 (half
// away from zero, clamped to +-16), MIN_LOD raised to 0, and which of bias,
// MAX_LOD (below 15) and MIN_LOD (above 0) apply; MIN_LOD == MAX_LOD fixes
// the LOD whatever the shader asks.
struct LodState {
    float bias = 0.0f, min_lod = 0.0f, max_lod = 1000.0f;
    bool bias_non_zero = false, apply_min = false, apply_max = false, equal = false;

    static LodState of(const Texture& t) {
        LodState s;
        s.bias = std::round(std::clamp(t.lod_bias, -16.0f, 16.0f) * 256.0f) / 256.0f;
        s.min_lod = std::max(t.min_lod, 0.0f);
        s.max_lod = t.max_lod;
        s.bias_non_zero = s.bias != 0.0f;
        s.apply_min = s.min_lod > 0.0f;
        s.apply_max = s.max_lod < 15.0f;
        s.equal = s.min_lod == s.max_lod;
        return s;
    }
    bool operator==(const LodState&) const = default;
    // GL's defaults: the selector's shortcut may run.
    bool plain() const { return !bias_non_zero && !apply_min && !apply_max && !equal; }
    // §2.4 step 4: the sampler's bias, then MAX_LOD, then MIN_LOD (a NaN
    // LOD becomes the bound, as minps/maxps give it).
    // The LOD of an explicit or biased request (textureLod, texture with a
    // bias): fixed when MIN_LOD == MAX_LOD, else adjusted.
    Float requested(Float lod) const { return equal ? Float(min_lod) : adjust(lod); }
    Float adjust(Float lod) const {
        if (bias_non_zero) lod = lod + Float(bias);
        if (apply_max) lod = select(lod < Float(max_lod), lod, Float(max_lod));
        if (apply_min) lod = select(lod > Float(min_lod), lod, Float(min_lod));
        return lod;
    }
};

}  // namespace st::texel
