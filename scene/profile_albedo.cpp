// profile_albedo.cpp: the Sec. 3.1 texture of profile_albedo.h.
#include "scene/profile_albedo.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <list>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/input_error.h"
#include "scene/profile_albedo_gather.h"

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

namespace {

// The freckles' centres in a grid of cubic cells a little over 4 radii
// wide: a freckle reaches a point only within 4 radii (q < 16), so only the
// 27 cells around the point can hold one that does. The largest Gaussian
// does not depend on the order the candidates come in, so the grid changes
// no bit of the map, only its cost (before it, every texel tried every
// freckle: 100,000 of them on a 4096 texture would take days).
class FreckleGrid {
public:
    FreckleGrid(const std::vector<glm::dvec3>& centres, double radius)
        : centres_(centres), cell_(4.0 * radius * 1.001) {
        for (size_t k = 0; k < centres.size(); ++k) cells_[cell_of(centres[k])].push_back(k);
    }
    // The map's darkening at p: the largest exp(-q) of a freckle with q < 16.
    double spot(const glm::dvec3& p, double r2) const {
        double spot = 0;
        const Cell at = cell_of(p);
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx) {
                    const auto it = cells_.find({at[0] + dx, at[1] + dy, at[2] + dz});
                    if (it == cells_.end()) continue;
                    for (size_t k : it->second) {
                        const glm::dvec3 d = p - centres_[k];
                        const double q = glm::dot(d, d) / r2;
                        if (q < 16) spot = std::max(spot, std::exp(-q));
                    }
                }
        return spot;
    }

private:
    using Cell = std::array<int64_t, 3>;
    struct CellHash {
        size_t operator()(const Cell& c) const {
            return size_t((uint64_t(c[0]) * 0x9e3779b97f4a7c15ull) ^ (uint64_t(c[1]) * 0xbf58476d1ce4e5b9ull) ^
                          (uint64_t(c[2]) * 0x94d049bb133111ebull));
        }
    };
    // Clamped far beyond any shape's cells (|p| <= 1e5 mm over cells of at
    // least 4e-3 mm: 2.5e7), so that the conversion is defined.
    Cell cell_of(const glm::dvec3& p) const {
        const auto c = [&](double x) { return int64_t(std::clamp(std::floor(x / cell_), -1e12, 1e12)); };
        return {c(p.x), c(p.y), c(p.z)};
    }
    const std::vector<glm::dvec3>& centres_;
    double cell_;
    std::unordered_map<Cell, std::vector<size_t>, CellHash> cells_;
};

// The largest side below `size` whose layout's gather stays within the
// budget: the terms grow as the side to the fourth while the windows are
// narrower than the layout, and at most so (a side of budget^(1/4) fits any
// reach).
int coarse_side(const ProfileShape& shape, int size, double terms, double reach99, double budget) {
    int side = size;
    while (terms > budget) {
        side = std::max(2, std::min(side - 1, int(side * 0.95 * std::pow(budget / terms, 0.25))));
        terms = gather_terms(texel_layout(shape, side), reach99);
    }
    return side;
}

// The map averaged over each texel of a side x side layout: k x k points
// spread evenly over the texel (k the fine texels it spans along an axis,
// rounded up), so that the map's detail is averaged where it lies rather
// than shifted to the coarse texel's centre.
std::array<std::vector<double>, 3> texel_means(const ProfileShape& shape, int side, int size,
                                               const std::function<std::array<double, 3>(const glm::dvec3&)>& map) {
    const size_t m = size_t(side) * size_t(side);
    std::array<std::vector<double>, 3> mean;
    for (std::vector<double>& v : mean) v.assign(m, 0.0);
    const int k = (size + side - 1) / side;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const size_t y = size_t(j) * side + size_t(i);
            for (int b = 0; b < k; ++b)
                for (int a = 0; a < k; ++a) {
                    const double u = (i + (a + 0.5) / k) / side, v = (j + (b + 0.5) / k) / side;
                    const std::array<double, 3> value = map(surface_point(shape, u, v).position);
                    for (int c = 0; c < 3; ++c) mean[size_t(c)][y] += value[size_t(c)];
                }
            for (int c = 0; c < 3; ++c) mean[size_t(c)][y] /= double(k) * k;
        }
    return mean;
}

// The coarse layout's values at the fine texels' centres, bilinear between
// the coarse texels' centres (wrapping in u where the layout does).
std::array<std::vector<double>, 3> bilinear_up(const std::array<std::vector<double>, 3>& coarse, int side, int size,
                                               bool wraps) {
    std::array<std::vector<double>, 3> out;
    for (std::vector<double>& o : out) o.resize(size_t(size) * size_t(size));
    const auto axis = [&](int i, bool wrap, int& i0, int& i1, double& f) {
        const double x = (i + 0.5) * side / size - 0.5;
        const double fl = std::floor(x);
        f = x - fl;
        i0 = int(fl), i1 = i0 + 1;
        if (wrap) {
            i0 = (i0 + side) % side, i1 = i1 % side;
        } else {
            i0 = std::clamp(i0, 0, side - 1), i1 = std::clamp(i1, 0, side - 1);
        }
    };
    for (int j = 0; j < size; ++j) {
        int j0, j1;
        double fv;
        axis(j, false, j0, j1, fv);
        for (int i = 0; i < size; ++i) {
            int i0, i1;
            double fu;
            axis(i, wraps, i0, i1, fu);
            const size_t x = size_t(j) * size + size_t(i);
            for (int c = 0; c < 3; ++c) {
                const std::vector<double>& v = coarse[size_t(c)];
                const double a = (1 - fu) * v[size_t(j0) * side + size_t(i0)] + fu * v[size_t(j0) * side + size_t(i1)];
                const double b = (1 - fu) * v[size_t(j1) * side + size_t(i0)] + fu * v[size_t(j1) * side + size_t(i1)];
                out[size_t(c)][x] = (1 - fv) * a + fv * b;
            }
        }
    }
    return out;
}

}  // namespace

Texture albedo_texture(const AlbedoMap& map, const ProfileShape& shape, const BuiltProfiles& profiles, bool thin,
                       int size, double gather_budget) {
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
    const TexelLayout layout = texel_layout(shape, size);

    // The map: white with darker freckles, each a Gaussian in world distance.
    SplitMix rng{map.seed};
    std::vector<glm::dvec3> centres;
    for (int k = 0; k < map.count; ++k) {
        const double u = rng.next(), xi = rng.next();
        // Uniform over a sphere's area on an ellipsoid (v = polar angle / pi), over the layout elsewhere.
        const double v = shape.kind == "ellipsoid" ? std::acos(1.0 - 2.0 * xi) / 3.14159265358979323846 : xi;
        centres.push_back(surface_point(shape, u, v).position);
    }
    const double r2 = map.radius_mm * map.radius_mm;
    const FreckleGrid freckles(centres, map.radius_mm);
    const auto map_at = [&](const glm::dvec3& p) {
        const double spot = freckles.spot(p, r2);
        return std::array<double, 3>{1.0 - map.strength[0] * spot, 1.0 - map.strength[1] * spot,
                                     1.0 - map.strength[2] * spot};
    };

    // The convolution with the profile: over the texture's own layout, or,
    // where the profile's reach spans so many texels that the gather would
    // pass its budget, over the largest coarser layout within it, from the
    // map averaged over each coarse texel, read back bilinearly (both are
    // quadratures of the same blur; docs/profile.md has how far apart).
    const ProfileTable table = profile_table(profiles, thin);
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    const double terms = gather_terms(layout, table.reach99);
    std::array<std::vector<double>, 3> blurred;
    if (terms <= gather_budget) {
        // Per channel (channel-major: the gather reads one channel's run of
        // neighbours at a time).
        std::array<std::vector<double>, 3> albedo;
        for (std::vector<double>& a : albedo) a.resize(n);
        for (size_t x = 0; x < n; ++x) {
            const std::array<double, 3> value = map_at(layout.p[x]);
            for (int c = 0; c < 3; ++c) albedo[size_t(c)][x] = value[size_t(c)];
        }
        blurred = gather(layout, albedo, table, threads);
    } else {
        const int side = coarse_side(shape, size, terms, table.reach99, gather_budget);
        const TexelLayout coarse = texel_layout(shape, side);
        blurred = bilinear_up(gather(coarse, texel_means(shape, side, size, map_at), table, threads), side, size,
                              coarse.wraps);
    }

    std::vector<float> out(n * 4);
    std::array<double, 3> mean{0, 0, 0};
    double total_area = 0;
    for (size_t x = 0; x < n; ++x) {
        for (int c = 0; c < 3; ++c) {
            const double v = blurred[size_t(c)][x];
            out[x * 4 + size_t(c)] = float(v);
            mean[size_t(c)] += v * layout.area[x];
        }
        out[x * 4 + 3] = 1.0f;
        total_area += layout.area[x];
    }
    // Normalised to a white mean over the surface (Sec. 3.1, second step).
    for (size_t x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c) out[x * 4 + size_t(c)] = float(out[x * 4 + size_t(c)] / (mean[size_t(c)] / total_area));
    t.texels32 = std::move(out);
    return t;
}

namespace {

// The inputs that decide a texture, exactly (doubles by their bits).
std::string texture_key(const AlbedoMap& m, const ProfileShape& s, const BuiltProfiles* profiles, bool thin, int size) {
    std::string key;
    const auto add = [&](double d) {
        uint64_t bits;
        std::memcpy(&bits, &d, sizeof bits);
        key += std::to_string(bits) + ",";
    };
    key += m.pattern + "," + std::to_string(m.count) + "," + std::to_string(m.seed) + ",";
    add(m.radius_mm);
    for (double v : m.strength) add(v);
    key += s.kind + "," + std::to_string(s.segments) + ",";
    for (double v : {s.size_mm, s.bend_deg, s.radii.x, s.radii.y, s.radii.z, s.seam_azimuth_deg}) add(v);
    key += std::to_string(reinterpret_cast<uintptr_t>(profiles)) + "," + (thin ? "1," : "0,") + std::to_string(size);
    return key;
}

}  // namespace

Texture scene_albedo_texture(const AlbedoMap& map, const ProfileShape& shape,
                             const std::shared_ptr<const BuiltProfiles>& profiles, bool thin, int size) {
    if (!map.textured()) return albedo_texture(map, shape, *profiles, thin, size);
    struct Entry {
        std::string key;
        std::shared_ptr<const BuiltProfiles> profiles;  // kept alive, so that its address names it alone
        Texture texture;
    };
    static std::mutex mutex;
    static std::list<Entry> kept;  // most recent first
    constexpr size_t kKeptBytes = size_t(64) << 20;
    const std::string key = texture_key(map, shape, profiles.get(), thin, size);
    {
        std::lock_guard<std::mutex> lock(mutex);
        for (auto it = kept.begin(); it != kept.end(); ++it)
            if (it->key == key) {
                kept.splice(kept.begin(), kept, it);
                return kept.front().texture;
            }
    }
    Texture t = albedo_texture(map, shape, *profiles, thin, size);
    const size_t bytes = t.texels32.size() * sizeof(float);
    if (bytes > kKeptBytes) return t;
    std::lock_guard<std::mutex> lock(mutex);
    kept.push_front({key, profiles, t});
    size_t total = 0;
    for (auto it = kept.begin(); it != kept.end();) {
        total += it->texture.texels32.size() * sizeof(float);
        it = total > kKeptBytes ? kept.erase(it) : std::next(it);
    }
    return t;
}

}  // namespace st
