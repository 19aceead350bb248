// profile_albedo.cpp: the Sec. 3.1 texture of profile_albedo.h.
#include "scene/profile_albedo.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/input_error.h"

namespace st {

namespace {

// splitmix64: the same stream on every platform (std's distributions are not).
struct SplitMix {
    uint64_t state;
    double next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
};

}  // namespace

AlbedoMap read_albedo_map(JsonReader& r) {
    AlbedoMap m;
    m.pattern = r.choice_or("pattern", "freckles", {"freckles"});
    m.count = r.integer_or("count", m.count, 1, 100000);
    m.radius_mm = r.number_or("radius_mm", m.radius_mm, 1e-3, 1e4);
    const std::vector<double> s = r.numbers("strength", 3, 3, 0.0, 0.95);
    m.strength = {s[0], s[1], s[2]};
    m.seed = uint64_t(r.integer_or("seed", 1, 0, 1 << 30));
    r.finish();
    return m;
}

Texture albedo_texture(const AlbedoMap& map, const ProfileShape& shape, const BuiltProfiles& profiles, bool thin,
                       int size) {
    Texture t;
    t.sampler = "albedo";
    t.set_filter(TextureFilter::Linear);
    if (!map.textured()) {
        t.format = TextureFormat::RGBA8;
        t.width = t.height = 1;
        t.texels8 = {255, 255, 255, 255};
        return t;
    }
    t.format = TextureFormat::RGBA32F;
    t.set_wrap(TextureWrap::ClampToEdge);
    if (shape.kind == "ellipsoid") t.wrap_s = TextureWrap::Repeat;
    t.width = t.height = size;
    const size_t n = size_t(size) * size_t(size);

    // Texel centres on the exact surface, and the area each covers.
    std::vector<glm::dvec3> p(n);
    std::vector<double> area(n);
    const double du = 1.0 / size;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double u = (i + 0.5) * du, v = (j + 0.5) * du;
            p[size_t(j) * size + size_t(i)] = surface_point(shape, u, v).position;
            const glm::dvec3 pu = surface_point(shape, u + 0.5 * du, v).position -
                                  surface_point(shape, u - 0.5 * du, v).position;
            const glm::dvec3 pv = surface_point(shape, u, v + 0.5 * du).position -
                                  surface_point(shape, u, v - 0.5 * du).position;
            area[size_t(j) * size + size_t(i)] = glm::length(glm::cross(pu, pv));
        }

    // The map: white with darker freckles, each a Gaussian in world distance.
    SplitMix rng{map.seed};
    std::vector<glm::dvec3> centres;
    for (int k = 0; k < map.count; ++k) {
        const double u = rng.next(), xi = rng.next();
        // Uniform over a sphere's area on an ellipsoid (v = polar angle / pi), over the layout elsewhere.
        const double v = shape.kind == "ellipsoid" ? std::acos(1.0 - 2.0 * xi) / 3.14159265358979323846 : xi;
        centres.push_back(surface_point(shape, u, v).position);
    }
    std::vector<std::array<double, 3>> albedo(n, {1.0, 1.0, 1.0});
    const double r2 = map.radius_mm * map.radius_mm;
    for (size_t x = 0; x < n; ++x) {
        double spot = 0;
        for (const glm::dvec3& c : centres) {
            const glm::dvec3 d = p[x] - c;
            const double q = glm::dot(d, d) / r2;
            if (q < 16) spot = std::max(spot, std::exp(-q));
        }
        for (int c = 0; c < 3; ++c) albedo[x][size_t(c)] = 1.0 - map.strength[size_t(c)] * spot;
    }

    // The convolution with the profile, within its reach, as a table of the
    // profile per channel in r (the profile's own interpolation is slow).
    const double reach = profiles.r_max;
    constexpr int kTable = 1024;
    std::vector<std::array<double, 3>> kernel(kTable + 1);
    for (int k = 0; k <= kTable; ++k) {
        const double r = reach * k / kTable;
        for (int c = 0; c < 3; ++c)
            kernel[size_t(k)][size_t(c)] = profiles.R[size_t(c)](r) + (thin ? profiles.T[size_t(c)](r) : 0.0);
    }
    // The texture's blur needs the profile's body, not its far tail (the
    // gather keeps that): the radius holding 99 % of each channel's weight.
    double reach99 = 0;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> cumulative(kTable + 1, 0.0);
        for (int k = 1; k <= kTable; ++k) {
            const double r0 = reach * (k - 1) / kTable, r1 = reach * k / kTable;
            cumulative[size_t(k)] = cumulative[size_t(k - 1)] + 0.5 * (kernel[size_t(k - 1)][size_t(c)] * r0 +
                                                                      kernel[size_t(k)][size_t(c)] * r1) * (r1 - r0);
        }
        int k = 0;
        while (k < kTable && cumulative[size_t(k)] < 0.99 * cumulative[kTable]) ++k;
        reach99 = std::max(reach99, reach * k / kTable);
    }
    std::vector<float> out(n * 4);
    std::array<double, 3> mean{0, 0, 0};
    double total_area = 0;
    const bool wraps = shape.kind == "ellipsoid";
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            const size_t x = size_t(j) * size + size_t(i);
            // The window of texels that can lie within the reach: the texel's
            // spacing along u and v here, at most half the layout.
            // (the next texel, or at the last row or column the one before it)
            const size_t xu = size_t(j) * size + size_t(i + 1 < size ? i + 1 : i - 1);
            const size_t xv = size_t(j + 1 < size ? j + 1 : j - 1) * size + size_t(i);
            const double su = std::max(glm::length(p[xu] - p[x]), 1e-9), sv = std::max(glm::length(p[xv] - p[x]), 1e-9);
            const int wu = std::min(size / 2, int(std::ceil(reach99 / su)) + 1);
            const int wv = std::min(size / 2, int(std::ceil(reach99 / sv)) + 1);
            std::array<double, 3> sum{0, 0, 0}, weight{0, 0, 0};
            for (int b = std::max(0, j - wv); b <= std::min(size - 1, j + wv); ++b) {
                for (int a = i - wu; a <= i + wu; ++a) {
                    int ai = a;
                    if (wraps) ai = (a % size + size) % size;
                    else if (a < 0 || a >= size) continue;
                    const size_t y = size_t(b) * size + size_t(ai);
                    const double r = glm::length(p[y] - p[x]);
                    if (!(r < reach99)) continue;
                    const double f = r / reach * kTable;
                    const int k = std::min(int(f), kTable - 1);
                    const double w = f - k;
                    for (int c = 0; c < 3; ++c) {
                        const double pr = (1 - w) * kernel[size_t(k)][size_t(c)] + w * kernel[size_t(k + 1)][size_t(c)];
                        sum[size_t(c)] += pr * area[y] * albedo[y][size_t(c)];
                        weight[size_t(c)] += pr * area[y];
                    }
                }
            }
            for (int c = 0; c < 3; ++c) {
                const double v = weight[size_t(c)] > 0 ? sum[size_t(c)] / weight[size_t(c)] : albedo[x][size_t(c)];
                out[x * 4 + size_t(c)] = float(v);
                mean[size_t(c)] += v * area[x];
            }
            out[x * 4 + 3] = 1.0f;
            total_area += area[x];
        }
    }
    // Normalised to a white mean over the surface (Sec. 3.1, second step).
    for (size_t x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c) out[x * 4 + size_t(c)] = float(out[x * 4 + size_t(c)] / (mean[size_t(c)] / total_area));
    t.texels32 = std::move(out);
    return t;
}

}  // namespace st
