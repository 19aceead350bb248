// framebuffer.h: an RGBA32F colour target with a 32-bit float depth buffer.
// Rows are in GL window order (row 0 at the bottom), as the rasterizer sees
// them; to_image() flips to the top-to-bottom order of st::Image.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/vec4.hpp>

#include "image/image.h"

namespace st {

struct Framebuffer {
    int width = 0, height = 0;
    std::vector<glm::vec4> colour;
    std::vector<float> depth;

    Framebuffer(int w, int h, glm::vec4 clear_colour, float clear_depth)
        : width(w), height(h), colour(size_t(w) * h, clear_colour), depth(size_t(w) * h, clear_depth) {}

    void clear(glm::vec4 clear_colour, float clear_depth) {
        std::fill(colour.begin(), colour.end(), clear_colour);
        std::fill(depth.begin(), depth.end(), clear_depth);
    }

    size_t index(int x, int y) const { return size_t(y) * width + x; }

    Image to_image() const {
        Image image(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::vec4& c = colour[index(x, height - 1 - y)];
                float* out = image.pixel(x, y);
                out[0] = c.r; out[1] = c.g; out[2] = c.b; out[3] = c.a;
            }
        return image;
    }
};

}  // namespace st
