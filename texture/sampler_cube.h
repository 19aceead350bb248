// sampler_cube.h: a cube map as the CPU twins sample it, with seamless
// filtering on (GL_TEXTURE_CUBE_MAP_SEAMLESS, as real renderers set it) and
// mip levels, filtered the way llvmpipe filters it
// (docs/llvmpipe/mipmaps-cubes-formats.md §5): face selection, projection,
// per-pixel LOD from the transformed derivatives, LINEAR taps that cross to
// the neighbouring face, and corners whose weight is shared in thirds.
#pragma once

#include <cstdint>
#include <vector>

#include "frame/frame.h"
#include "simd/lane_vec.h"
#include "texture/level_table.h"
#include "texture/lod_state.h"

namespace st {

namespace texel {
struct LevelChoice;
}

class SamplerCube {
public:
    // texture.cube must hold six square faces (+X, -X, +Y, -Y, +Z, -Z) per
    // level, and min_filter == mag_filter (the min/mag switch on cubes is
    // not modelled; scenes reject it).
    explicit SamplerCube(const Texture& texture);

    // GLSL texture(samplerCube, vec3): LOD per pixel from the quad.
    Vec4 sample(const Vec3& dir) const;
    // GLSL texture(samplerCube, vec3, float bias): the pixel's LOD plus the bias.
    Vec4 sample_bias(const Vec3& dir, Float bias) const;
    // GLSL textureLod(samplerCube, vec3, float).
    Vec4 sample_lod(const Vec3& dir, Float lod) const;
    // GLSL textureGrad(samplerCube, vec3, vec3 dPdx, vec3 dPdy).
    Vec4 sample_grad(const Vec3& dir, const Vec3& dpdx, const Vec3& dpdy) const;

    struct Face;

private:
    Float project_rho2(const Vec3& dir, const Vec3& ddx, const Vec3& ddy, Face& f) const;
    Vec4 sample_at(const Face& f, const texel::LevelChoice& c) const;
    Vec4 filter_level(const Face& f, Int level) const;
    void nearest_unorm8(const Face& f, Int level, Int& rb, Int& ga) const;
    // A level's face size and first texel, per lane.
    struct LevelLanes {
        Int size, base;
    };
    LevelLanes level_lanes(Int level) const;
    Vec4 texel(const LevelLanes& level, Int face, Int x, Int y) const;

    const Texture* tex_;
    int last_level_ = 0;
    MipFilter mip_filter_ = MipFilter::None;
    texel::LodState lod_;
    bool aos_ = false;  // RGBA8 NEAREST: llvmpipe's 8-bit path
    // Each level's face size and where its texels start in the arrays below.
    texel::LevelTable level_size_, level_base_;
    std::vector<int32_t> rgba8_;
    std::vector<float> rgba32_;
};

}  // namespace st
