// mip_generation.cpp: see mip_generation.h.
#include "texture/mip_generation.h"

#include "texture/srgb.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace st {

int full_chain_levels(int width, int height) {
    int levels = 1;
    while ((width >> levels) > 0 || (height >> levels) > 0) ++levels;
    return levels;
}

namespace {

// Level-0 texels as doubles, RGBA, every face.
std::vector<double> base_texels(const Texture& t) {
    const size_t n = size_t(t.width) * size_t(t.height) * 4 * size_t(t.faces());
    std::vector<double> out(n);
    for (size_t i = 0; i < n; ++i)
        out[i] = t.format == TextureFormat::RGBA8          ? t.texels8[i] / 255.0
                 : t.format == TextureFormat::SRGB8_ALPHA8 ? (i % 4 == 3 ? t.texels8[i] / 255.0 : srgb_to_linear(t.texels8[i] / 255.0))
                                                           : double(t.texels32[i]);
    return out;
}

// Destination texel x of a level n texels wide covers [x * W / n, (x + 1) *
// W / n) of level 0; each source texel counts with the length it overlaps.
std::vector<std::pair<int, double>> footprint(int x, int n, int base) {
    const double lo = double(x) * base / n, hi = double(x + 1) * base / n;
    std::vector<std::pair<int, double>> taps;
    for (int i = int(std::floor(lo)); i < int(std::ceil(hi)); ++i) {
        const double w = std::min(hi, double(i + 1)) - std::max(lo, double(i));
        if (w > 0) taps.push_back({i, w / (hi - lo)});
    }
    return taps;
}

// One face of level l from the same face of level 0 (`base`, doubles).
void box_face(const Texture& t, const std::vector<double>& base, int face, TextureLevel& l) {
    const size_t base_face = size_t(face) * size_t(t.height) * size_t(t.width);
    const size_t level_face = size_t(face) * size_t(l.height) * size_t(l.width);
    for (int y = 0; y < l.height; ++y) {
        const auto ty = footprint(y, l.height, t.height);
        for (int x = 0; x < l.width; ++x) {
            const auto tx = footprint(x, l.width, t.width);
            double sum[4] = {0, 0, 0, 0};
            for (const auto& [j, wy] : ty)
                for (const auto& [i, wx] : tx) {
                    const double* texel = &base[(base_face + size_t(j) * size_t(t.width) + size_t(i)) * 4];
                    for (int c = 0; c < 4; ++c) sum[c] += wx * wy * texel[c];
                }
            const size_t o = (level_face + size_t(y) * size_t(l.width) + size_t(x)) * 4;
            for (int c = 0; c < 4; ++c) {
                if (t.format == TextureFormat::SRGB8_ALPHA8 && c < 3)  // filtered in linear, stored encoded
                    l.texels8[o + size_t(c)] = uint8_t(std::lround(linear_to_srgb(sum[c]) * 255.0));
                else if (holds_bytes(t.format))
                    l.texels8[o + size_t(c)] = uint8_t(std::lround(std::clamp(sum[c], 0.0, 1.0) * 255.0));
                else
                    l.texels32[o + size_t(c)] = float(sum[c]);
            }
        }
    }
}

}  // namespace

void generate_box_mips(Texture& t, int levels) {
    const std::vector<double> base = base_texels(t);
    t.mips.clear();
    for (int level = 1; level < levels; ++level) {
        TextureLevel l;
        l.width = std::max(1, t.width >> level);
        l.height = std::max(1, t.height >> level);
        const size_t n = size_t(l.width) * size_t(l.height) * 4 * size_t(t.faces());
        if (holds_bytes(t.format)) l.texels8.resize(n);
        else l.texels32.resize(n);
        for (int face = 0; face < t.faces(); ++face) box_face(t, base, face, l);
        t.mips.push_back(std::move(l));
    }
}

bool mip_sizes_valid(const Texture& t, std::string& why) {
    for (size_t i = 0; i < t.mips.size(); ++i) {
        const int level = int(i) + 1;
        const int w = std::max(1, t.width >> level), h = std::max(1, t.height >> level);
        const TextureLevel& l = t.mips[i];
        const size_t n = size_t(w) * size_t(h) * 4 * size_t(t.faces());
        const size_t have = holds_bytes(t.format) ? l.texels8.size() : l.texels32.size();
        if (l.width != w || l.height != h || have != n) {
            why = "level " + std::to_string(level) + " is " + std::to_string(l.width) + "x" +
                  std::to_string(l.height) + ", expected " + std::to_string(w) + "x" + std::to_string(h);
            return false;
        }
        if (w == 1 && h == 1 && i + 1 < t.mips.size()) {
            why = "levels past 1x1";
            return false;
        }
    }
    return true;
}

}  // namespace st
