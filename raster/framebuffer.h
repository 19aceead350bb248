// framebuffer.h: an RGBA32F colour target with a 32-bit float depth buffer,
// stored the way the fragment stage writes it: tile by tile (64x64, row-major
// over tiles, GL window order, row 0 at the bottom), so that a tile's pixels
// are one contiguous stretch of memory; in a tile, 4x4 blocks row-major;
// each block as its two
// 8-lane groups (shading/block_layout.h), and each group channel by
// channel, 8 values in lane order. The lanes of one group are then 8
// consecutive floats per channel, so depth test and blending load and store
// whole vectors. to_image() converts to the top-to-bottom RGBA rows of
// st::Image.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/vec4.hpp>

#include "image/image.h"
#include "raster/tile_raster.h"
#include "shading/block_layout.h"

namespace st {

struct Framebuffer {
    static constexpr int kGroupFloats = 4 * kGroupLanes;  // one group's colour

    int width = 0, height = 0;
    static constexpr int kTileBlocks = kTileSize / kBlockSize;  // blocks on a tile's side

    int blocks_x = 0, blocks_y = 0;
    int tiles_x = 0, tiles_y = 0;
    std::vector<float> colour;  // [block][group][channel][lane]
    std::vector<float> depth;   // [block][group][lane]

    Framebuffer(int w, int h)
        : width(w), height(h), blocks_x((w + kBlockSize - 1) / kBlockSize), blocks_y((h + kBlockSize - 1) / kBlockSize),
          tiles_x((blocks_x + kTileBlocks - 1) / kTileBlocks), tiles_y((blocks_y + kTileBlocks - 1) / kTileBlocks),
          colour(size_t(tiles_x) * tiles_y * kTileBlocks * kTileBlocks * 4 * kBlockLanes),
          depth(size_t(tiles_x) * tiles_y * kTileBlocks * kTileBlocks * kBlockLanes) {}

    // The block whose lower-left pixel is (x, y), both multiples of 4.
    size_t block(int x, int y) const {
        const int bx = x / kBlockSize, by = y / kBlockSize;
        const size_t tile = size_t(by / kTileBlocks) * size_t(tiles_x) + size_t(bx / kTileBlocks);
        return tile * kTileBlocks * kTileBlocks + size_t(by % kTileBlocks) * kTileBlocks + size_t(bx % kTileBlocks);
    }
    // Channel ch of lane i of group g is group_colour(b, g)[ch * 8 + i].
    float* group_colour(size_t b, int g) { return &colour[(b * 2 + size_t(g)) * kGroupFloats]; }
    float* group_depth(size_t b, int g) { return &depth[(b * 2 + size_t(g)) * kGroupLanes]; }

    glm::vec4 pixel(int x, int y) const {
        const size_t b = block(x & ~(kBlockSize - 1), y & ~(kBlockSize - 1));
        const int lane = block_lane(x & (kBlockSize - 1), y & (kBlockSize - 1));
        const float* c = &colour[(b * 2 + size_t(lane / kGroupLanes)) * kGroupFloats + size_t(lane % kGroupLanes)];
        return glm::vec4(c[0], c[kGroupLanes], c[2 * kGroupLanes], c[3 * kGroupLanes]);
    }

    // The colour as RGBA texels, row 0 at the bottom (glReadPixels order),
    // rows [4 * block_row, 4 * block_row + 4) of them into `out` (sized for
    // the whole image), block by block: a render target's copy from one pass
    // to the next, one job per block row on the worker pool. load_texels()
    // is the way back.
    void texels_of_block_row(int block_row, float* out) const {
        const int y0 = block_row * kBlockSize;
        for (int bx = 0; bx < blocks_x; ++bx) {
            const int x0 = bx * kBlockSize;
            const float* block_colour = &colour[block(x0, y0) * 2 * kGroupFloats];
            for (int dy = 0; dy < kBlockSize && y0 + dy < height; ++dy)
                for (int dx = 0; dx < kBlockSize && x0 + dx < width; ++dx) {
                    const int lane = block_lane(dx, dy);
                    const float* c = block_colour + (lane / kGroupLanes) * kGroupFloats + lane % kGroupLanes;
                    float* o = out + (size_t(y0 + dy) * size_t(width) + size_t(x0 + dx)) * 4;
                    o[0] = c[0], o[1] = c[kGroupLanes], o[2] = c[2 * kGroupLanes], o[3] = c[3 * kGroupLanes];
                }
        }
    }

    void load_texels(const std::vector<float>& in) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const size_t b = block(x & ~(kBlockSize - 1), y & ~(kBlockSize - 1));
                const int lane = block_lane(x & (kBlockSize - 1), y & (kBlockSize - 1));
                float* c = &colour[(b * 2 + size_t(lane / kGroupLanes)) * kGroupFloats + size_t(lane % kGroupLanes)];
                const float* i = &in[(size_t(y) * size_t(width) + size_t(x)) * 4];
                for (int ch = 0; ch < 4; ++ch) c[ch * kGroupLanes] = i[ch];
            }
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
