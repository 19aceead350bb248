// profile_albedo_gather.cpp: the gather of profile_albedo_gather.h.
#include "scene/profile_albedo_gather.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <system_error>
#include <thread>

#include <glm/geometric.hpp>

namespace st {

TexelLayout texel_layout(const ProfileShape& shape, int size) {
    TexelLayout l;
    l.size = size;
    l.wraps = shape.kind == "ellipsoid";
    const size_t n = size_t(size) * size_t(size);
    l.p.resize(n);
    l.area.resize(n);
    const double du = 1.0 / size;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double u = (i + 0.5) * du, v = (j + 0.5) * du;
            l.p[size_t(j) * size + size_t(i)] = surface_point(shape, u, v).position;
            const glm::dvec3 pu = surface_point(shape, u + 0.5 * du, v).position -
                                  surface_point(shape, u - 0.5 * du, v).position;
            const glm::dvec3 pv = surface_point(shape, u, v + 0.5 * du).position -
                                  surface_point(shape, u, v - 0.5 * du).position;
            l.area[size_t(j) * size + size_t(i)] = glm::length(glm::cross(pu, pv));
        }
    return l;
}

ProfileTable profile_table(const BuiltProfiles& profiles, bool thin) {
    ProfileTable t;
    constexpr int kTable = ProfileTable::kSize;
    t.reach = profiles.r_max;
    for (std::vector<double>& k : t.k) k.resize(kTable + 1);
    for (int k = 0; k <= kTable; ++k) {
        const double r = t.reach * k / kTable;
        for (int c = 0; c < 3; ++c)
            t.k[size_t(c)][size_t(k)] = profiles.R[size_t(c)](r) + (thin ? profiles.T[size_t(c)](r) : 0.0);
    }
    for (int c = 0; c < 3; ++c) {
        std::vector<double> cumulative(kTable + 1, 0.0);
        for (int k = 1; k <= kTable; ++k) {
            const double r0 = t.reach * (k - 1) / kTable, r1 = t.reach * k / kTable;
            cumulative[size_t(k)] = cumulative[size_t(k - 1)] + 0.5 * (t.k[size_t(c)][size_t(k - 1)] * r0 +
                                                                      t.k[size_t(c)][size_t(k)] * r1) * (r1 - r0);
        }
        int k = 0;
        while (k < kTable && cumulative[size_t(k)] < 0.99 * cumulative[kTable]) ++k;
        t.reach99 = std::max(t.reach99, t.reach * k / kTable);
    }
    return t;
}

namespace {

// The window of texels that can lie within reach99 of texel (i, j): the
// texel's spacing along u and v there (to the next texel, or at the last
// row or column the one before it), at most half the layout. (In double
// until the minimum: reach99 over a spacing can pass any int.)
struct Window {
    int wu, wv;
};
Window window_at(const TexelLayout& l, int i, int j, double reach99) {
    const int size = l.size;
    const size_t x = size_t(j) * size + size_t(i);
    const size_t xu = size_t(j) * size + size_t(i + 1 < size ? i + 1 : i - 1);
    const size_t xv = size_t(j + 1 < size ? j + 1 : j - 1) * size + size_t(i);
    const double su = std::max(glm::length(l.p[xu] - l.p[x]), 1e-9), sv = std::max(glm::length(l.p[xv] - l.p[x]), 1e-9);
    return {int(std::min(double(size / 2), std::ceil(reach99 / su) + 1)),
            int(std::min(double(size / 2), std::ceil(reach99 / sv) + 1))};
}

// One row of a texel's window: each neighbour's share of the weights,
// whether it lies within reach99, in the order the sums take them.
struct RowTerms {
    std::vector<double> weight[3], sum[3];
    std::vector<unsigned char> within;
    explicit RowTerms(size_t m) {
        for (int c = 0; c < 3; ++c) weight[c].resize(m), sum[c].resize(m);
        within.resize(m);
    }
};

// Row j of the gather into out (channel-major), with the layout's
// coordinates as separate arrays so that the first loop runs over the
// machine's lanes.
void gather_row(const TexelLayout& l, const std::vector<double>& px, const std::vector<double>& py,
                const std::vector<double>& pz, const std::array<std::vector<double>, 3>& albedo,
                const ProfileTable& table, int j, RowTerms& terms, std::array<std::vector<double>, 3>& out) {
    constexpr int kTable = ProfileTable::kSize;
    const int size = l.size;
    const double reach = table.reach, reach99 = table.reach99;
    for (int i = 0; i < size; ++i) {
        const size_t x = size_t(j) * size + size_t(i);
        const auto [wu, wv] = window_at(l, i, j, reach99);
        // The columns i - wu ... i + wu in order, wrapped where the layout
        // wraps (at most two runs, and 2 wu + 1 <= size + 1 of them),
        // clipped elsewhere.
        int runs[2][2], run_count = 0;
        if (!l.wraps) {
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
                const double *a_ = l.area.data() + first, *al0 = albedo[0].data() + first,
                             *al1 = albedo[1].data() + first, *al2 = albedo[2].data() + first;
                const double *k0 = table.k[0].data(), *k1 = table.k[1].data(), *k2 = table.k[2].data();
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
        for (int c = 0; c < 3; ++c)
            out[size_t(c)][x] = weight[size_t(c)] > 0 ? sum[size_t(c)] / weight[size_t(c)] : albedo[size_t(c)][x];
    }
}

}  // namespace

double gather_terms(const TexelLayout& l, double reach99) {
    double terms = 0;
    for (int j = 0; j < l.size; ++j)
        for (int i = 0; i < l.size; ++i) {
            const auto [wu, wv] = window_at(l, i, j, reach99);
            const int columns = l.wraps ? 2 * wu + 1 : std::min(l.size - 1, i + wu) - std::max(0, i - wu) + 1;
            const int rows = std::min(l.size - 1, j + wv) - std::max(0, j - wv) + 1;
            terms += double(columns) * rows;
        }
    return terms;
}

std::array<std::vector<double>, 3> gather(const TexelLayout& l, const std::array<std::vector<double>, 3>& albedo,
                                          const ProfileTable& table, int threads) {
    const size_t n = l.p.size();
    std::vector<double> px(n), py(n), pz(n);
    for (size_t x = 0; x < n; ++x) px[x] = l.p[x].x, py[x] = l.p[x].y, pz[x] = l.p[x].z;
    std::array<std::vector<double>, 3> out;
    for (std::vector<double>& o : out) o.resize(n);

    // Rows handed out one at a time; each worker's scratch allocated here,
    // so that nothing a worker does can throw.
    const int workers = std::max(1, std::min(threads, l.size));
    std::vector<RowTerms> scratch(size_t(workers), RowTerms(size_t(l.size) + 1));
    std::atomic<int> next{0};
    const auto work = [&](RowTerms& terms) {
        for (int j; (j = next.fetch_add(1)) < l.size;) gather_row(l, px, py, pz, albedo, table, j, terms, out);
    };
    // A thread the system will not start leaves its rows to the others.
    std::vector<std::thread> pool;
    for (int w = 1; w < workers; ++w) {
        try {
            pool.emplace_back(work, std::ref(scratch[size_t(w)]));
        } catch (const std::system_error&) {
            break;
        }
    }
    work(scratch[0]);
    for (std::thread& t : pool) t.join();
    return out;
}

}  // namespace st
