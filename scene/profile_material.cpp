// profile_material.cpp: a material's profiles, tables and sample pattern
// (profile_material.h), built once per material and process.
#include "scene/profile_material.h"

#include <chrono>
#include <limits>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <sstream>

#include "optics/multipole.h"
#include "optics/profile_table.h"
#include "optics/radial_sampler.h"
#include "optics/rough_surface.h"
#include "scene/input_error.h"

namespace st {

namespace {

std::array<double, 3> rgb(JsonReader& r, const std::string& key, double lo, double hi) {
    const std::vector<double> v = r.numbers(key, 1, 3, lo, hi);
    if (v.size() == 2) throw InputError("field '" + r.field(key) + "' needs one value or three (R, G, B)");
    return v.size() == 1 ? std::array<double, 3>{v[0], v[0], v[0]} : std::array<double, 3>{v[0], v[1], v[2]};
}

Texture table_texture(const std::string& sampler, int width, std::vector<float> texels, TextureFilter filter) {
    Texture t;
    t.sampler = sampler;
    t.format = TextureFormat::RGBA32F;
    t.set_filter(filter);
    t.set_wrap(TextureWrap::ClampToEdge);
    t.width = width;
    t.height = 1;
    t.texels32 = std::move(texels);
    return t;
}

std::string key_of(const ProfileMaterial& m, const GatherSettings& g) {
    std::ostringstream k;
    k.precision(17);
    k << m.model << ' ' << m.g << ' ' << m.eta << ' ' << m.thickness << ' ' << m.roughness;
    for (int c = 0; c < 3; ++c) k << ' ' << m.sigma_a[size_t(c)] << ' ' << m.sigma_s[size_t(c)];
    k << ' ' << g.pattern << ' ' << g.samples << ' ' << g.table_size << ' ' << g.tail_fraction;
    return k.str();
}

std::shared_ptr<BuiltProfiles> build(const ProfileMaterial& m, const GatherSettings& g) {
    const auto start = std::chrono::steady_clock::now();
    auto out = std::make_shared<BuiltProfiles>();
    std::shared_ptr<const optics::RoughSurface> rough;
    if (m.roughness > 0) rough = std::make_shared<optics::RoughSurface>(m.roughness, m.eta);
    for (int c = 0; c < 3; ++c) {
        optics::Slab s;
        s.sigma_a = m.sigma_a[size_t(c)];
        s.sigma_s = m.sigma_s[size_t(c)];
        s.g = m.g;
        s.eta = m.eta;
        s.thickness = m.thin() ? m.thickness : std::numeric_limits<double>::infinity();
        if (rough) s.boundary_factor_top = optics::rough_boundary_factor(m.roughness, m.eta);
        // The dipole is the multipole's central pair alone (Jensen et al. 2001).
        auto mp = std::make_shared<const optics::Multipole>(
            m.model == "dipole" ? optics::Multipole(s, 0) : optics::Multipole::converged(s, 1e-4));
        out->R[size_t(c)] = [mp](double r) { return mp->reflectance(r); };
        out->T[size_t(c)] = [mp](double r) { return mp->transmittance(r); };
        out->total_R[size_t(c)] = mp->total_reflectance();
        out->total_T[size_t(c)] = m.thin() ? mp->total_transmittance() : 0.0;
        out->dipoles = std::max(out->dipoles, mp->dipoles());
    }
    // What the gather weighs: the reflectance, and for thin geometry the
    // transmittance too, averaged over the channels.
    const auto gathered = [out, thin = m.thin()](double r) {
        double p = 0;
        for (int c = 0; c < 3; ++c) p += out->R[size_t(c)](r) + (thin ? out->T[size_t(c)](r) : 0.0);
        return p / 3.0;
    };
    // The reach: the widest channel's, where R (and T) leave out
    // tail_fraction of their totals.
    double reach = 0;
    for (int c = 0; c < 3; ++c) {
        const auto R = out->R[size_t(c)], T = out->T[size_t(c)];
        const bool thin = m.thin();
        const optics::RadialSampler channel([R, T, thin](double r) { return R(r) + (thin ? T(r) : 0.0); },
                                            g.tail_fraction);
        reach = std::max(reach, channel.r_max());
    }
    out->r_max = reach;
    std::vector<float> tr(size_t(g.table_size) * 4), tt(size_t(g.table_size) * 4);
    for (int c = 0; c < 3; ++c) {
        const optics::ProfileTable table(out->R[size_t(c)], out->T[size_t(c)], reach, g.table_size);
        for (int i = 0; i < g.table_size; ++i) {
            tr[size_t(i) * 4 + size_t(c)] = table.texels()[size_t(i) * 4 + 0];
            tt[size_t(i) * 4 + size_t(c)] = table.texels()[size_t(i) * 4 + 1];
        }
    }
    for (int i = 0; i < g.table_size; ++i) tr[size_t(i) * 4 + 3] = tt[size_t(i) * 4 + 3] = 1.0f;
    out->profile_R = table_texture("profile_R", g.table_size, std::move(tr), TextureFilter::Linear);
    out->profile_T = table_texture("profile_T", g.table_size, std::move(tt), TextureFilter::Linear);

    // The pattern: each sample's offset and the area it stands for, so that
    // the gather's sum of E P dA is the integral's estimate either way.
    std::vector<float> p(size_t(g.samples) * 4);
    if (g.pattern == "importance") {
        const optics::RadialSampler sampler(gathered, g.tail_fraction);
        const std::vector<optics::GatherSample> ks = sampler.importance_pattern(g.samples);
        for (size_t k = 0; k < ks.size(); ++k) {
            const double r = std::hypot(ks[k].x, ks[k].y);
            p[k * 4 + 0] = float(ks[k].x), p[k * 4 + 1] = float(ks[k].y);
            p[k * 4 + 2] = float(ks[k].weight / gathered(r));  // (total / n) / P(r): the area per sample
        }
    } else {  // "disk": uniform over the reach, a Vogel spiral
        const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
        for (int k = 0; k < g.samples; ++k) {
            const double r = reach * std::sqrt((k + 0.5) / g.samples), a = k * golden;
            p[size_t(k) * 4 + 0] = float(r * std::cos(a)), p[size_t(k) * 4 + 1] = float(r * std::sin(a));
            p[size_t(k) * 4 + 2] = float(std::numbers::pi * reach * reach / g.samples);
        }
    }
    out->pattern = table_texture("pattern", g.samples, std::move(p), TextureFilter::Nearest);

    std::vector<float> rho(4, 1.0f);
    int rho_n = 1;
    if (rough) {
        rho_n = 32;
        const std::vector<double> table = rough->rho_dt_table(rho_n);
        rho.assign(size_t(rho_n) * 4, 1.0f);
        for (int i = 0; i < rho_n; ++i) rho[size_t(i) * 4] = rho[size_t(i) * 4 + 1] = rho[size_t(i) * 4 + 2] = float(table[size_t(i)]);
    }
    out->rho_dt = table_texture("rho_dt", rho_n, std::move(rho), TextureFilter::Linear);
    out->build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace

ProfileMaterial read_profile_material(JsonReader& r) {
    ProfileMaterial m;
    m.model = r.choice_or("model", "multipole", {"dipole", "multipole"});
    m.sigma_a = rgb(r, "sigma_a", 1e-9, 1e6);
    m.sigma_s = rgb(r, "sigma_s", 0.0, 1e6);
    m.g = r.number_or("g", 0.0, -0.99, 0.99);
    m.eta = r.number_or("eta", 1.3, 1.0, 3.0);
    m.thickness = r.has("thickness_mm") ? r.number("thickness_mm", 1e-4, 1e4) : 0.0;
    m.roughness = r.number_or("roughness", 0.0, 0.0, 2.0);
    if (m.roughness > 0 && m.roughness < 0.05)
        throw InputError("field '" + r.field("roughness") +
                         "': below 0.05 the lobe is too narrow for the rho_dt quadrature; give 0 (smooth) or more");
    r.finish();
    return m;
}

std::shared_ptr<const BuiltProfiles> build_profiles(const ProfileMaterial& m, const GatherSettings& g) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const BuiltProfiles>> cache;
    const std::string key = key_of(m, g);
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) {
        auto again = std::make_shared<BuiltProfiles>(*it->second);
        again->build_ms = 0;
        return again;
    }
    std::shared_ptr<const BuiltProfiles> built;
    try {
        built = build(m, g);
    } catch (const std::invalid_argument& e) {
        throw InputError("field 'material': its profile cannot be built: " + std::string(e.what()));
    }
    cache[key] = built;
    return built;
}

}  // namespace st
