// sampler2d.h: a 2D texture as the CPU twins sample it, filtered the way
// llvmpipe filters it: level selection from the quad's derivatives or an
// explicit LOD, then the 8-bit AoS or the float SoA filter of each level
// (sampler2d.cpp has the arithmetic; docs/llvmpipe/texture-sampling.md and
// mipmaps-cubes-formats.md the facts behind it).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "simd/lane_vec.h"
#include "texture/bilinear_taps.h"
#include "texture/level_table.h"
#include "texture/lod_selection.h"
#include "texture/lod_state.h"

namespace st {

class Sampler2D {
public:
    explicit Sampler2D(const Texture& texture);

    // GLSL texture(sampler2D, vec2): in a fragment twin the LOD comes from
    // each 2x2 quad of lanes (its top-left, top-right and bottom-left
    // lanes, as llvmpipe takes it), so call it on whole quads. `read` as
    // for sample_lod: the channels the shader uses (texel::kReadR for .r);
    // the others read anything, and filtering may skip them. `active`: the
    // lanes whose result is used (exec.active() for a value stored with
    // exec.assign); the others still give the quad's LOD their coordinates
    // but read anything, so their work may be skipped where that keeps
    // every active lane's bits.
    Vec4 sample(const Vec2& st, unsigned read = texel::kReadRGBA, Mask active = Mask(true)) const;
    // texture()'s levels at a coordinate, chosen once for every read there
    // (as a compiler shares the coordinate's derivatives between reads):
    // sample(st, levels) equals sample(st) bit for bit on this sampler and
    // on any other whose texture has the same size, levels and LOD state; a
    // sampler of another shape chooses its own levels from st.
    struct ImplicitLevels {
        texel::LevelChoice choice;
        texel::LodShape shape;
    };
    ImplicitLevels implicit_levels(const Vec2& st) const;
    Vec4 sample(const Vec2& st, const ImplicitLevels& levels, unsigned read = texel::kReadRGBA,
                Mask active = Mask(true)) const;
    // GLSL texture(sampler2D, vec2, float bias): the quad's LOD plus each
    // lane's bias.
    Vec4 sample_bias(const Vec2& st, Float bias) const;
    // GLSL textureLod(sampler2D, vec2, float): one LOD per lane. `read`
    // (texel::kReadRGB for .rgb) names the channels used; the sampler may
    // then skip the others (they read anything).
    ST_INLINE Vec4 sample_lod(const Vec2& st, Float lod, unsigned read = texel::kReadRGBA) const {
        if (clamped_bilinear_) return sample_lod(bilinear_taps(st), read);
        return sample_lod_levels(st, lod, read);
    }
    // textureLod(…, st, 0.0) on several textures of one size and sampler
    // state, with the taps found once (texture/bilinear_taps.h): each
    // sample_lod(taps, read) equals sample_lod(st, 0, read) bit for bit, on
    // any texture (one of another shape or state samples taps.st afresh).
    BilinearTaps bilinear_taps(const Vec2& st) const;
    Vec4 sample_lod(const BilinearTaps& taps, unsigned read = texel::kReadRGBA) const;
    // GLSL textureGrad(sampler2D, vec2, vec2 dPdx, vec2 dPdy): per lane.
    Vec4 sample_grad(const Vec2& st, const Vec2& dpdx, const Vec2& dpdy) const;
    // textureGrad's levels depend on the derivatives alone, not on the
    // coordinate: a search that reads one texture at many points with the
    // same derivatives chooses them once (as LLVM hoists that computation
    // out of llvmpipe's loop) and samples with the second form; the result
    // is the same as sample_grad(st, dpdx, dpdy), bit for bit.
    texel::LevelChoice grad_levels(const Vec2& dpdx, const Vec2& dpdy) const;
    Vec4 sample_grad(const Vec2& st, const texel::LevelChoice& levels) const;
    // sample_grad(st, levels).w alone: a height read. On the 8-bit path
    // the red and blue pair is then neither filtered nor blended.
    Float sample_grad_alpha(const Vec2& st, const texel::LevelChoice& levels) const;
    // GLSL textureSize(sampler2D, lod).x and .y (lane 0's lod decides, as
    // in llvmpipe; 0 for a level outside the chain).
    Int size_x(Int lod) const;
    Int size_y(Int lod) const;
    // GLSL texelFetch(sampler2D, ivec2, level); out-of-range texels and
    // levels return 0 (with the format's swizzle: R32F gives (0, 0, 0, 1)).
    Vec4 fetch(Int x, Int y, Int level = Int(0)) const;

    // One lane of the above, for vertex twins and host code (no quad, so
    // texture() there is textureLod(…, 0), as Mesa lowers it).
    glm::vec4 sample(const glm::vec2& st) const;
    glm::vec4 fetch(int x, int y) const;

    // The texels of a float texture changed and nothing else did (a render
    // target that a later pass samples, refreshed each frame): copies them
    // in again from `levels` (its levels' RGBA floats, as the texture would
    // hold them; not read from the texture), into the arrays the
    // constructor made, without allocating.
    void reload_texels(const std::vector<std::vector<float>>& levels);

    const Texture& texture() const { return *tex_; }
    int width() const { return tex_->width; }
    int height() const { return tex_->height; }

    // A level's size and where its texels start, one value per lane (lanes
    // may sample different levels).
    struct LevelLanes {
        Int width, height;
        Float width_f, height_f;
        Int base;  // index of the level's first texel
    };

private:
    using LevelChoice = texel::LevelChoice;
    Vec4 sample_lod_levels(const Vec2& st, Float lod, unsigned read) const;

    LevelLanes level_lanes(Int level) const;
    bool needs_lod() const;
    Vec4 sample_base(const Vec2& st, unsigned read = texel::kReadRGBA, Mask active = Mask(true)) const;
    Float quad_rho2(const Vec2& st) const;
    Vec4 sample_levels(const Vec2& st, const LevelChoice& choice, bool per_quad_lod,
                       unsigned read = texel::kReadRGBA, Mask active = Mask(true)) const;
    Vec4 filter_levels(const Vec2& st, const LevelChoice& choice, TextureFilter filter, bool aos, unsigned read,
                       Mask active) const;
    Vec4 blend_second_level(const Vec2& st, const LevelChoice& choice, TextureFilter filter, Mask as_nearest,
                            Mask blend, const Vec4& c0, unsigned read) const;
    Vec4 filter_float(const Vec2& st, const LevelLanes& level, TextureFilter filter, Mask as_nearest,
                      unsigned read = texel::kReadRGBA) const;
    Int texture_size(Int lod, bool x) const;
    void filter_unorm8(const Vec2& st, const LevelLanes& level, TextureFilter filter, bool level0, unsigned read,
                       Mask active, Int& rb, Int& ga) const;
    Vec4 texel(const LevelLanes& level, Int x, Int y, unsigned read = texel::kReadRGBA) const;
    void row_pair(const LevelLanes& level, const texel::LinearTaps& u, Int y, unsigned read, Vec4& left,
                  Vec4& right) const;
    void load_texels(size_t texels, const std::vector<std::vector<float>>* float_levels = nullptr);
    void build_alpha_quads();
    Int alpha_bilinear(const Vec2& st, const LevelLanes& level) const;

    const Texture* tex_;
    int last_level_ = 0;
    // One float level, LINEAR, CLAMP_TO_EDGE on both axes: sample_lod is
    // the inlined filter of texture/clamped_bilinear.h.
    bool clamped_bilinear_ = false;
    bool aos_ = false;        // RGBA8 with REPEAT/CLAMP_TO_EDGE: llvmpipe's 8-bit path
    bool pot_w_ = true, pot_h_ = true;
    MipFilter mip_filter_ = MipFilter::None;
    texel::LodState lod_;
    texel::LodShape shape_;
    // Each level's size and where its texels start in the arrays below.
    texel::LevelTable level_width_, level_height_, level_base_;
    // RGBA8 texels of every level as one int32 each (little-endian: R in the
    // low byte), and kLanes more, so that a texel and its right neighbour
    // are always one 8-byte load and a row of kLanes texels one load.
    std::vector<int32_t> rgba8_;
    // For height reads (sample_grad_alpha) of a mip-mapped bilinear RGBA8
    // texture: at each texel of each level, the alpha bytes of its 2x2
    // footprint (the texel, its right, lower and lower-right neighbours
    // under the texture's wraps), so that one 4-byte gather fetches all
    // four taps. Empty for other textures.
    std::vector<int32_t> alpha_quads_;
    // The float formats' texels as stored (texture/texel_formats.h), RGBA.
    std::vector<float> rgba32_;
};

}  // namespace st

#include "texture/clamped_bilinear.h"
