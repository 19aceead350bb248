// sampler2d.h: a 2D texture as the CPU twins sample it, filtered the way
// llvmpipe filters it (see sampler2d.cpp for the arithmetic of each path).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "simd/lane_vec.h"

namespace st {

class Sampler2D {
public:
    explicit Sampler2D(const Texture& texture);

    // GLSL texture(sampler2D, vec2) without mipmaps.
    glm::vec4 sample(const glm::vec2& st) const;
    // GLSL texelFetch(sampler2D, ivec2, 0); out-of-range texels return 0.
    glm::vec4 fetch(int x, int y) const;

    // The same for every lane of a fragment twin at once; the calls above
    // are one lane of these.
    Vec4 sample(const Vec2& st) const;
    Vec4 fetch(Int x, Int y) const;

    int width() const { return tex_->width; }
    int height() const { return tex_->height; }

private:
    Vec4 sample_nearest(const Vec2& st) const;
    Vec4 sample_linear_float(const Vec2& st) const;
    Vec4 sample_linear_unorm8(const Vec2& st) const;

    const Texture* tex_;
    // RGBA8 texels as one int32 each (little-endian: R in the low byte), and
    // kLanes more, so that a texel and its right neighbour are always one
    // 8-byte load and a row of kLanes texels from any texel one load.
    std::vector<int32_t> rgba8_;
};

}  // namespace st
