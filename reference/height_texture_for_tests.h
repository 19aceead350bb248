// height_texture_for_tests.h: the height maps and random numbers the relief
// reference tests use (relief_intersection_test.cpp, relief_sampled_crossing_test.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "frame/frame.h"

namespace st::reference::testing_maps {

// An RGBA8 REPEAT texture whose alpha is `alpha` (row-major, row 0 at t = 0),
// with a box-filtered mip chain down to 1x1 when `mips` is set.
inline Texture height_texture(int w, int h, const std::vector<uint8_t>& alpha, bool mips = true) {
    Texture t;
    t.format = TextureFormat::RGBA8;
    t.set_wrap(TextureWrap::Repeat);
    t.set_filter(TextureFilter::Linear);  // trilinear, as the relief maps are
    t.mip_filter = mips ? MipFilter::Linear : MipFilter::None;
    t.width = w;
    t.height = h;
    const auto rgba = [](const std::vector<uint8_t>& a) {
        std::vector<uint8_t> texels(a.size() * 4, 0);
        for (size_t i = 0; i < a.size(); ++i) texels[i * 4 + 3] = a[i];
        return texels;
    };
    t.texels8 = rgba(alpha);
    std::vector<uint8_t> level = alpha;
    while (mips && (w > 1 || h > 1)) {
        const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
        std::vector<uint8_t> next(size_t(nw) * nh);
        for (int y = 0; y < nh; ++y)
            for (int x = 0; x < nw; ++x) {
                int sum = 0, n = 0;
                for (int dy = 0; dy < (h > 1 ? 2 : 1); ++dy)
                    for (int dx = 0; dx < (w > 1 ? 2 : 1); ++dx, ++n)
                        sum += level[size_t(y * (h > 1 ? 2 : 1) + dy) * w + x * (w > 1 ? 2 : 1) + dx];
                next[size_t(y) * nw + x] = uint8_t((sum + n / 2) / n);
            }
        t.mips.push_back(TextureLevel{nw, nh, rgba(next), {}});
        level = std::move(next);
        w = nw;
        h = nh;
    }
    return t;
}

// Portable uniform doubles (std::uniform_real_distribution is not).
struct Rng {
    std::mt19937_64 gen;
    explicit Rng(uint64_t seed) : gen(seed) {}
    double uniform(double a, double b) { return a + (b - a) * double(gen() >> 11) * 0x1p-53; }
    int below(int n) { return int(gen() % uint64_t(n)); }
};

}  // namespace st::reference::testing_maps
