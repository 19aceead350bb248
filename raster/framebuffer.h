// framebuffer.h: an RGBA32F colour target with a 32-bit float depth buffer,
// stored the way the fragment stage writes it: in 4x4 blocks (row-major
// over blocks, GL window order, row 0 at the bottom), and inside a block
// channel by channel, each channel's 16 values in block lane order
// (shading/block_layout.h). A part of a block that a twin shaded is then
// kLanes consecutive floats per channel, so depth test and blending load and
// store whole vectors. to_image() converts to the top-to-bottom RGBA rows
// of st::Image.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/vec4.hpp>

#include "image/image.h"
#include "shading/block_layout.h"

namespace st {

struct Framebuffer {
    int width = 0, height = 0;
    int blocks_x = 0, blocks_y = 0;
    std::vector<float> colour;  // [block][channel][lane]
    std::vector<float> depth;   // [block][lane]

    Framebuffer(int w, int h, glm::vec4 clear_colour, float clear_depth)
        : width(w), height(h), blocks_x((w + kBlockSize - 1) / kBlockSize), blocks_y((h + kBlockSize - 1) / kBlockSize),
          colour(size_t(blocks_x) * blocks_y * 4 * kBlockLanes), depth(size_t(blocks_x) * blocks_y * kBlockLanes) {
        clear(clear_colour, clear_depth);
    }

    void clear(glm::vec4 clear_colour, float clear_depth) {
        for (size_t b = 0; b < colour.size(); b += 4 * kBlockLanes)
            for (int c = 0; c < 4; ++c)
                std::fill_n(colour.begin() + ptrdiff_t(b) + c * kBlockLanes, kBlockLanes, clear_colour[c]);
        std::fill(depth.begin(), depth.end(), clear_depth);
    }

    // The block whose lower-left pixel is (x, y), both multiples of 4.
    size_t block(int x, int y) const { return size_t(y / kBlockSize) * blocks_x + size_t(x / kBlockSize); }
    float* block_colour(size_t b) { return &colour[b * 4 * kBlockLanes]; }  // + channel * kBlockLanes + lane
    float* block_depth(size_t b) { return &depth[b * kBlockLanes]; }

    glm::vec4 pixel(int x, int y) const {
        const size_t b = block(x & ~(kBlockSize - 1), y & ~(kBlockSize - 1));
        const int lane = block_lane(x & (kBlockSize - 1), y & (kBlockSize - 1));
        const float* c = &colour[b * 4 * kBlockLanes + size_t(lane)];
        return glm::vec4(c[0], c[kBlockLanes], c[2 * kBlockLanes], c[3 * kBlockLanes]);
    }

    Image to_image() const {
        Image image(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::vec4 c = pixel(x, height - 1 - y);
                float* out = image.pixel(x, y);
                out[0] = c.r; out[1] = c.g; out[2] = c.b; out[3] = c.a;
            }
        return image;
    }
};

}  // namespace st
