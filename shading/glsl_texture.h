// glsl_texture.h: GLSL's texture functions under their GLSL names, so that
// a twin's line reads as its shader's: `texture(*tex_, uv)` for
// `texture(tex, uv)`. Each forwards to the sampler (texture/sampler2d.h,
// texture/sampler_cube.h), which computes what llvmpipe computes; the
// fragment forms take the LOD of texture() from each 2x2 quad of lanes, so
// call them on every lane (in a loop, lanes that have left keep their
// coordinates). Not in glsl_math.h: only twins that sample need the
// samplers' headers.
#pragma once

#include "shading/control_flow.h"
#include "texture/sampler2d.h"
#include "texture/sampler_cube.h"

namespace st::glsl {

// sampler2D, fragment twins (lanes).
inline Vec4 texture(const Sampler2D& s, const Vec2& p) { return s.sample(p); }
inline Vec4 texture(const Sampler2D& s, const Vec2& p, const Float& bias) { return s.sample_bias(p, bias); }
// texture() whose result is stored with exec.assign, and of which the
// shader uses the channels in `read` (texel::kReadR for .r): the lanes
// exec leaves out and the other channels read anything, so the sampler may
// skip them (a loop's last pass reads nothing), the active lanes' bits
// unchanged. The LOD still comes from every lane of each quad.
inline Vec4 texture(const Sampler2D& s, const Vec2& p, const Exec& exec, unsigned read = texel::kReadRGBA) {
    return s.sample(p, read, exec.active());
}
inline Vec4 textureLod(const Sampler2D& s, const Vec2& p, const Float& lod) { return s.sample_lod(p, lod); }
inline Vec4 textureGrad(const Sampler2D& s, const Vec2& p, const Vec2& dpdx, const Vec2& dpdy) {
    return s.sample_grad(p, dpdx, dpdy);
}
inline Vec4 texelFetch(const Sampler2D& s, const IVec2& p, const Int& lod) { return s.fetch(p.x, p.y, lod); }
inline IVec2 textureSize(const Sampler2D& s, const Int& lod) { return IVec2(s.size_x(lod), s.size_y(lod)); }

// samplerCube, fragment twins (lanes).
inline Vec4 texture(const SamplerCube& s, const Vec3& dir) { return s.sample(dir); }
inline Vec4 texture(const SamplerCube& s, const Vec3& dir, const Float& bias) { return s.sample_bias(dir, bias); }
inline Vec4 textureLod(const SamplerCube& s, const Vec3& dir, const Float& lod) { return s.sample_lod(dir, lod); }
inline Vec4 textureGrad(const SamplerCube& s, const Vec3& dir, const Vec3& dpdx, const Vec3& dpdy) {
    return s.sample_grad(dir, dpdx, dpdy);
}

// sampler2D, vertex twins (one vertex): no quad, so texture() is
// textureLod(..., 0.0), as Mesa lowers it in a vertex shader.
inline glm::vec4 texture(const Sampler2D& s, const glm::vec2& p) { return s.sample(p); }

}  // namespace st::glsl
