// framebuffer_test.cpp: a target's texels copied out block row by block
// row are its pixels in glReadPixels order, whatever the size (edges of
// partial blocks and tiles included), and load_texels() puts them back.
#include "raster/framebuffer.h"

#include <gtest/gtest.h>

namespace st {
namespace {

TEST(Framebuffer, BlockRowsAreThePixelsInRowOrder) {
    struct Size {
        int w, h;
    };
    for (const Size& k : {Size{13, 7}, Size{64, 64}, Size{70, 5}, Size{1, 1}, Size{130, 67}}) {
        Framebuffer fb(k.w, k.h);
        for (size_t i = 0; i < fb.colour.size(); ++i) fb.colour[i] = float(i) * 0.25f;
        std::vector<float> texels(size_t(k.w) * size_t(k.h) * 4, -1.0f);
        for (int row = 0; row < fb.blocks_y; ++row) fb.texels_of_block_row(row, texels.data());
        for (int y = 0; y < k.h; ++y)
            for (int x = 0; x < k.w; ++x) {
                const glm::vec4 p = fb.pixel(x, y);
                for (int c = 0; c < 4; ++c)
                    ASSERT_EQ(texels[(size_t(y) * size_t(k.w) + size_t(x)) * 4 + size_t(c)], p[c])
                        << k.w << "x" << k.h << " at " << x << "," << y;
            }
        Framebuffer back(k.w, k.h);
        back.load_texels(texels);
        for (int y = 0; y < k.h; ++y)
            for (int x = 0; x < k.w; ++x) ASSERT_EQ(back.pixel(x, y), fb.pixel(x, y));
    }
}

}  // namespace
}  // namespace st
