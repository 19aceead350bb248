// thin_slab_textures.cpp: see thin_slab_textures.h.
#include "scene/thin_slab_textures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "scene/texture_patterns.h"

namespace st {

namespace {


Texture rgba8(const std::string& sampler, int w, int h) {
    Texture t;
    t.sampler = sampler;
    t.format = TextureFormat::RGBA8;
    t.set_filter(TextureFilter::Linear);
    t.set_wrap(TextureWrap::ClampToEdge);
    t.width = w;
    t.height = h;
    t.texels8.resize(size_t(w) * h * 4);
    return t;
}

void put(Texture& t, int x, int y, double r, double g, double b) {
    uint8_t* p = &t.texels8[(size_t(y) * t.width + x) * 4];
    p[0] = unit_to_byte(r);
    p[1] = unit_to_byte(g);
    p[2] = unit_to_byte(b);
    p[3] = 255;
}

// Smooth value noise from a hashed lattice, in [0, 1].
double hash01(int x, int y) {
    uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return double(h & 0xffffff) / double(0xffffff);
}

double value_noise(double x, double y) {
    const int ix = int(std::floor(x)), iy = int(std::floor(y));
    const double fx = x - ix, fy = y - iy;
    const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const double a = hash01(ix, iy), b = hash01(ix + 1, iy), c = hash01(ix, iy + 1), d = hash01(ix + 1, iy + 1);
    return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy;
}

}  // namespace

Texture faroe_flag_texture(int width, int height) {
    Texture t = rgba8("flag", width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // Position in flag units: 22 across, 16 up; the cross is centred
            // 8 units from the hoist and 8 units up.
            const double u = (x + 0.5) * 22.0 / width, v = (y + 0.5) * 16.0 / height;
            const double du = std::abs(u - 8.0), dv = std::abs(v - 8.0);
            if (du < 1.0 || dv < 1.0) put(t, x, y, 239 / 255.0, 48 / 255.0, 62 / 255.0);       // red
            else if (du < 2.0 || dv < 2.0) put(t, x, y, 0 / 255.0, 101 / 255.0, 189 / 255.0);  // blue
            else put(t, x, y, 1.0, 1.0, 1.0);                                                  // white
        }
    return t;
}

Texture painting_texture(int width, int height) {
    Texture t = rgba8("painting", width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double u = (x + 0.5) / width, v = (y + 0.5) / height;  // v = 0 at the bottom
            const double wash = value_noise(u * 9.0, v * 9.0) * 0.6 + value_noise(u * 31.0, v * 31.0) * 0.4;
            const double hills = 0.42 + 0.08 * std::sin(u * 7.0 + 1.0) + 0.05 * std::sin(u * 17.0) + 0.03 * (wash - 0.5);
            const double sea = 0.22 + 0.015 * std::sin(u * 23.0);
            double r, g, b;
            if (v > hills) {  // sky: pale blue to white towards the horizon
                const double k = (v - hills) / (1.0 - hills);
                r = 0.80 - 0.25 * k + 0.06 * wash;
                g = 0.87 - 0.17 * k + 0.05 * wash;
                b = 0.93 - 0.02 * k + 0.04 * wash;
            } else if (v > sea) {  // green-brown hills
                const double k = (v - sea) / (hills - sea);
                r = 0.30 + 0.15 * k + 0.10 * wash;
                g = 0.45 + 0.10 * k + 0.10 * wash;
                b = 0.25 + 0.05 * k + 0.05 * wash;
            } else {  // sea
                r = 0.20 + 0.08 * wash;
                g = 0.35 + 0.10 * wash;
                b = 0.55 + 0.12 * wash;
            }
            put(t, x, y, r, g, b);
        }
    return t;
}

}  // namespace st
