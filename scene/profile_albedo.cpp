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
    // Domains and defaults: scene/profile_space.cpp.
    m.pattern = r.choice("pattern");
    m.count = r.integer("count");
    m.radius_mm = r.number("radius_mm");
    const std::vector<double> s = r.numbers("strength");
    m.strength = {s[0], s[1], s[2]};
    m.seed = uint64_t(r.integer("seed"));
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
    // Per channel (channel-major: the gather below reads one channel's run
    // of neighbours at a time).
    std::array<std::vector<double>, 3> albedo;
    for (std::vector<double>& a : albedo) a.assign(n, 1.0);
    const double r2 = map.radius_mm * map.radius_mm;
    for (size_t x = 0; x < n; ++x) {
        double spot = 0;
        for (const glm::dvec3& c : centres) {
            const glm::dvec3 d = p[x] - c;
            const double q = glm::dot(d, d) / r2;
            if (q < 16) spot = std::max(spot, std::exp(-q));
        }
        for (int c = 0; c < 3; ++c) albedo[size_t(c)][x] = 1.0 - map.strength[size_t(c)] * spot;
    }

    // The convolution with the profile, within its reach, as a table of the
    // profile per channel in r (the profile's own interpolation is slow).
    const double reach = profiles.r_max;
    constexpr int kTable = 1024;
    std::array<std::vector<double>, 3> kernel;
    for (std::vector<double>& k : kernel) k.resize(kTable + 1);
    for (int k = 0; k <= kTable; ++k) {
        const double r = reach * k / kTable;
        for (int c = 0; c < 3; ++c)
            kernel[size_t(c)][size_t(k)] = profiles.R[size_t(c)](r) + (thin ? profiles.T[size_t(c)](r) : 0.0);
    }
    // The texture's blur needs the profile's body, not its far tail (the
    // gather keeps that): the radius holding 99 % of each channel's weight.
    double reach99 = 0;
    for (int c = 0; c < 3; ++c) {
        std::vector<double> cumulative(kTable + 1, 0.0);
        for (int k = 1; k <= kTable; ++k) {
            const double r0 = reach * (k - 1) / kTable, r1 = reach * k / kTable;
            cumulative[size_t(k)] = cumulative[size_t(k - 1)] + 0.5 * (kernel[size_t(c)][size_t(k - 1)] * r0 +
                                                                      kernel[size_t(c)][size_t(k)] * r1) * (r1 - r0);
        }
        int k = 0;
        while (k < kTable && cumulative[size_t(k)] < 0.99 * cumulative[kTable]) ++k;
        reach99 = std::max(reach99, reach * k / kTable);
    }
    // The positions as separate coordinate arrays too, so that the gather's
    // first loop runs over the lanes of the machine.
    std::vector<double> px(n), py(n), pz(n);
    for (size_t x = 0; x < n; ++x) px[x] = p[x].x, py[x] = p[x].y, pz[x] = p[x].z;
    // One row of a texel's window: each neighbour's share of the weights,
    // whether it lies within reach99, in the order the sums take them.
    struct RowTerms {
        std::vector<double> weight[3], sum[3];
        std::vector<unsigned char> within;
        void resize(size_t m) {
            for (int c = 0; c < 3; ++c) weight[c].resize(m), sum[c].resize(m);
            within.resize(m);
        }
    } terms;
    terms.resize(size_t(size) + 1);

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
            // The columns i - wu ... i + wu in order, wrapped on an ellipsoid
            // (at most two runs, and 2 wu + 1 <= size + 1 of them), clipped
            // elsewhere.
            int runs[2][2], run_count = 0;
            if (!wraps) {
                runs[0][0] = std::max(0, i - wu), runs[0][1] = std::min(size - 1, i + wu), run_count = 1;
            } else if (i - wu < 0) {
                runs[0][0] = i - wu + size, runs[0][1] = size - 1, runs[1][0] = 0, runs[1][1] = i + wu, run_count = 2;
            } else if (i + wu >= size) {
                runs[0][0] = i - wu, runs[0][1] = size - 1, runs[1][0] = 0, runs[1][1] = i + wu - size, run_count = 2;
            } else {
                runs[0][0] = i - wu, runs[0][1] = i + wu, run_count = 1;
            }
            const double qx = px[x], qy = py[x], qz = pz[x];
            std::array<double, 3> sum{0, 0, 0}, weight{0, 0, 0};
            for (int b = std::max(0, j - wv); b <= std::min(size - 1, j + wv); ++b) {
                // Each neighbour's terms, independent of the others: the
                // distance as glm::length computes it ((dx dx + dy dy) + dz dz),
                // the profile read linearly from its table.
                size_t m = 0;
                for (int run = 0; run < run_count; ++run) {
                    const size_t first = size_t(b) * size + size_t(runs[run][0]);
                    const int count = runs[run][1] - runs[run][0] + 1;
                    const double *qx_ = px.data() + first, *qy_ = py.data() + first, *qz_ = pz.data() + first;
                    const double *a_ = area.data() + first, *al0 = albedo[0].data() + first,
                                 *al1 = albedo[1].data() + first, *al2 = albedo[2].data() + first;
                    const double *k0 = kernel[0].data(), *k1 = kernel[1].data(), *k2 = kernel[2].data();
                    double *w0 = terms.weight[0].data() + m, *w1 = terms.weight[1].data() + m,
                           *w2 = terms.weight[2].data() + m;
                    double *s0 = terms.sum[0].data() + m, *s1 = terms.sum[1].data() + m, *s2 = terms.sum[2].data() + m;
                    unsigned char* in = terms.within.data() + m;
                    // (No branch: the division is done for every neighbour and
                    // its result dropped beyond reach99, so that the loop runs
                    // over the machine's lanes.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep  // the rows' arrays are distinct (clang checks at run time)
#endif
                    for (int t = 0; t < count; ++t) {
                        const double dx = qx_[t] - qx, dy = qy_[t] - qy, dz = qz_[t] - qz;
                        const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
                        const bool within = r < reach99;
                        const double f_any = r / reach * kTable;
                        const double f = within ? f_any : 0.0;
                        const int k = std::min(int(f), kTable - 1);
                        const double w = f - k;
                        const double pr0 = (1 - w) * k0[k] + w * k0[k + 1];
                        const double pr1 = (1 - w) * k1[k] + w * k1[k + 1];
                        const double pr2 = (1 - w) * k2[k] + w * k2[k + 1];
                        w0[t] = pr0 * a_[t], w1[t] = pr1 * a_[t], w2[t] = pr2 * a_[t];
                        s0[t] = pr0 * a_[t] * al0[t], s1[t] = pr1 * a_[t] * al1[t], s2[t] = pr2 * a_[t] * al2[t];
                        in[t] = within;
                    }
                    m += size_t(count);
                }
                // The sums in window order, as one texel after another.
                for (size_t t = 0; t < m; ++t) {
                    if (!terms.within[t]) continue;
                    for (int c = 0; c < 3; ++c) {
                        sum[size_t(c)] += terms.sum[c][t];
                        weight[size_t(c)] += terms.weight[c][t];
                    }
                }
            }
            for (int c = 0; c < 3; ++c) {
                const double v = weight[size_t(c)] > 0 ? sum[size_t(c)] / weight[size_t(c)] : albedo[size_t(c)][x];
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
