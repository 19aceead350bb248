// profile_material.cpp: a material's profiles, tables and sample pattern
// (profile_material.h), built once per material and process.
#include "scene/profile_material.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "optics/monte_carlo.h"
#include "optics/multipole.h"
#include "optics/profile_table.h"
#include "optics/radial_sampler.h"
#include "optics/rough_surface.h"
#include "scene/input_error.h"
#include "scene/layer_file.h"
#include "scene/param_space.h"
#include "scene/profile_cache.h"

namespace st {

namespace {

constexpr int kMcBins = 400;

// Whether channel c's coefficients repeat an earlier channel's (a grey
// layer), whose Monte Carlo run need not be repeated.
int same_as_earlier(const std::vector<optics::LayerSpec>& layers, int c) {
    for (int e = 0; e < c; ++e)
        if (std::all_of(layers.begin(), layers.end(), [&](const optics::LayerSpec& l) {
                return l.sigma_a[size_t(e)] == l.sigma_a[size_t(c)] && l.sigma_s[size_t(e)] == l.sigma_s[size_t(c)];
            }))
            return e;
    return -1;
}

std::array<double, 3> rgb(JsonReader& r, const std::string& key) {
    const std::vector<double> v = r.numbers(key);
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

// Everything a material's profiles depend on, to 17 digits.
std::string profile_key(const ProfileMaterial& m) {
    std::ostringstream k;
    k.precision(17);
    k << "v1 " << m.model;
    for (const optics::LayerSpec& l : m.layers) {
        k << " [" << l.g << ' ' << l.eta << ' ' << l.thickness << ' ' << l.roughness;
        for (int c = 0; c < 3; ++c) k << ' ' << l.sigma_a[size_t(c)] << ' ' << l.sigma_s[size_t(c)];
        k << ']';
    }
    if (m.model == "mc") k << " mc " << m.photons << ' ' << m.seed << ' ' << m.mc_r_max;
    if (m.model == "multipole") k << " pairs " << m.max_dipole_pairs;
    return k.str();
}

// A tabulated profile read linearly between its radii: the first value
// below the first radius, 0 beyond the last, never negative (the layered
// profiles ring a little about 0 far out).
std::function<double(double)> interpolated(std::shared_ptr<const std::vector<double>> radii,
                                           std::shared_ptr<const std::vector<double>> values) {
    return [radii, values](double r) {
        const std::vector<double>& x = *radii;
        const std::vector<double>& y = *values;
        if (!(r > x.front())) return std::max(y.front(), 0.0);
        if (!(r < x.back())) return 0.0;
        const size_t i = size_t(std::upper_bound(x.begin(), x.end(), r) - x.begin()) - 1;
        const double w = (r - x[i]) / (x[i + 1] - x[i]);
        return std::max(y[i] + w * (y[i + 1] - y[i]), 0.0);
    };
}

TabulatedProfiles layered_profiles(const ProfileMaterial& m) {
    optics::LayeredOptions options;
    const optics::LayeredResult r = optics::combine_layers(m.layers, options);
    TabulatedProfiles t;
    t.radii = r.radii;
    for (int c = 0; c < 3; ++c) {
        t.R[size_t(c)] = r.channel[size_t(c)].R_profile;
        t.T[size_t(c)] = r.channel[size_t(c)].T_profile;
    }
    for (int d : r.dipoles) t.dipoles = std::max(t.dipoles, d);
    return t;
}

TabulatedProfiles mc_profiles(const ProfileMaterial& m) {
    TabulatedProfiles t;
    for (int c = 0; c < 3; ++c) {
        if (const int e = same_as_earlier(m.layers, c); e >= 0) {
            t.R[size_t(c)] = t.R[size_t(e)];
            t.T[size_t(c)] = t.T[size_t(e)];
            continue;
        }
        optics::McSetup setup;
        double n = 1.0;
        for (const optics::LayerSpec& l : m.layers) {
            n *= l.eta;
            setup.layers.push_back(optics::McLayer{l.sigma_a[size_t(c)], l.sigma_s[size_t(c)], l.g, n, l.thickness});
        }
        setup.top_roughness = m.roughness();
        setup.photons = uint64_t(m.photons);
        setup.seed = m.seed;
        setup.bins = kMcBins;
        setup.bin_width = m.mc_r_max / kMcBins;
        const optics::McResult r = optics::trace_photons(setup);
        t.radii = r.bin_centres;
        t.R[size_t(c)] = r.R_profile;
        t.T[size_t(c)] = r.T_profile;
    }
    return t;
}

std::shared_ptr<BuiltProfiles> build(const ProfileMaterial& m, const GatherSettings& g, const std::string& key) {
    const auto start = std::chrono::steady_clock::now();
    auto out = std::make_shared<BuiltProfiles>();
    out->source = "built";
    std::shared_ptr<const optics::RoughSurface> rough;
    if (m.roughness() > 0) rough = std::make_shared<optics::RoughSurface>(m.roughness(), m.eta());
    if (m.model == "dipole" || m.model == "multipole") {
        const optics::LayerSpec& l = m.layers.front();
        for (int c = 0; c < 3; ++c) {
            optics::Slab s;
            s.sigma_a = l.sigma_a[size_t(c)];
            s.sigma_s = l.sigma_s[size_t(c)];
            s.g = l.g;
            s.eta = l.eta;
            s.eta_below = l.eta;  // in air on both sides: its index relative to the air below
            s.thickness = l.thickness;
            if (rough) s.boundary_factor_top = optics::rough_boundary_factor(m.roughness(), m.eta());
            // The dipole is the multipole's central pair alone (Jensen et al. 2001).
            auto mp = std::make_shared<const optics::Multipole>(
                m.model == "dipole" ? optics::Multipole(s, 0)
                                    : optics::Multipole::converged(s, 1e-4, optics::SourceDepth::FirstScatter,
                                                                   m.max_dipole_pairs + 1));
            if (mp->pairs_per_side() > m.max_dipole_pairs)
                throw InputError("field '" + m.max_pairs_field + "': channel " + std::to_string(c) +
                                 "'s multipole needs more than " + std::to_string(m.max_dipole_pairs) +
                                 " dipole pairs per side to converge; raise the limit or thicken the slab");
            out->R[size_t(c)] = [mp](double r) { return mp->reflectance(r); };
            out->T[size_t(c)] = [mp](double r) { return mp->transmittance(r); };
            out->dipoles = std::max(out->dipoles, mp->dipoles());
        }
    } else {
        std::optional<TabulatedProfiles> t = load_cached_profiles(key);
        if (t) {
            out->source = "disk";
        } else {
            t = m.model == "layered" ? layered_profiles(m) : mc_profiles(m);
            store_cached_profiles(key, *t);
        }
        out->dipoles = t->dipoles;
        const auto radii = std::make_shared<const std::vector<double>>(t->radii);
        out->knots = t->radii;
        for (int c = 0; c < 3; ++c) {
            out->R[size_t(c)] = interpolated(radii, std::make_shared<const std::vector<double>>(t->R[size_t(c)]));
            out->T[size_t(c)] = interpolated(radii, std::make_shared<const std::vector<double>>(t->T[size_t(c)]));
        }
    }
    const bool thin = m.thin();
    // The reach: the widest channel's, where R (and T) leave out
    // tail_fraction of their totals.
    double reach = 0;
    for (int c = 0; c < 3; ++c) {
        const auto R = out->R[size_t(c)], T = out->T[size_t(c)];
        const optics::RadialSampler channel([R, T, thin](double r) { return R(r) + (thin ? T(r) : 0.0); },
                                            g.tail_fraction);
        reach = std::max(reach, channel.r_max());
        out->total_R[size_t(c)] = optics::radial_total(R, g.tail_fraction);
        out->total_T[size_t(c)] = thin ? optics::radial_total(T, g.tail_fraction) : 0.0;
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

    // What the gather weighs: the reflectance, and for thin geometry the
    // transmittance too, averaged over the channels.
    const auto gathered = [out, thin](double r) {
        double p = 0;
        for (int c = 0; c < 3; ++c) p += out->R[size_t(c)](r) + (thin ? out->T[size_t(c)](r) : 0.0);
        return p / 3.0;
    };
    // The pattern: each sample's offset and the area it stands for, so that
    // the gather's sum of E P dA is the integral's estimate either way.
    std::vector<float> p(size_t(g.samples) * 4);
    if (g.pattern == "importance") {
        const optics::RadialSampler sampler(gathered, g.tail_fraction);
        const std::vector<optics::GatherSample> ks = sampler.importance_pattern(g.samples);
        for (size_t k = 0; k < ks.size(); ++k) {
            const double r = std::hypot(ks[k].x, ks[k].y), density = gathered(r);
            p[k * 4 + 0] = float(ks[k].x), p[k * 4 + 1] = float(ks[k].y);
            // (total / n) / P(r): the area per sample (none where a
            // tabulated profile is 0 between its radii).
            p[k * 4 + 2] = density > 0 ? float(ks[k].weight / density) : 0.0f;
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
        for (int i = 0; i < rho_n; ++i)
            rho[size_t(i) * 4] = rho[size_t(i) * 4 + 1] = rho[size_t(i) * 4 + 2] = float(table[size_t(i)]);
    }
    out->rho_dt = table_texture("rho_dt", rho_n, std::move(rho), TextureFilter::Linear);
    out->build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

std::mutex& log_mutex() {
    static std::mutex m;
    return m;
}
std::vector<std::string>& build_log() {
    static std::vector<std::string> log;
    return log;
}

}  // namespace

bool ProfileMaterial::thin() const { return std::isfinite(layers.back().thickness); }

double ProfileMaterial::thickness() const {
    double d = 0;
    for (const optics::LayerSpec& l : layers) d += l.thickness;
    return d;
}

// Every field's domain and default: scene/profile_space.cpp.
ProfileMaterial read_profile_material(JsonReader& r) {
    ProfileMaterial m;
    m.model = r.choice("model");
    if (r.has("layers")) {
        // In the layer-file format, which parse_layers checks.
        const FieldSpec& layers = r.spec("layers");
        const nlohmann::json& list = r.array("layers", layers.min_len, layers.max_len);
        m.layers = parse_layers(list, "field '" + r.field("layers") + "'");
    } else if (r.has("layers_file")) {
        m.layers = read_layer_file(r.text("layers_file"));
    } else {
        // One slab, its fields inline; thickness_mm absent: semi-infinite.
        optics::LayerSpec l;
        l.sigma_a = rgb(r, "sigma_a");
        l.sigma_s = rgb(r, "sigma_s");
        l.g = r.number("g");
        l.eta = r.number("eta");
        l.thickness = r.has("thickness_mm") ? r.number("thickness_mm") : std::numeric_limits<double>::infinity();
        l.roughness = r.number("roughness");
        m.layers = {l};
    }
    // The stack seen from below (the back of a leaf): the layers in reverse,
    // each index relative to the one it now lies under.
    if (r.boolean("flip")) {
        std::vector<optics::LayerSpec> flipped(m.layers.rbegin(), m.layers.rend());
        double index = 1.0;
        std::vector<double> absolute;
        for (const optics::LayerSpec& l : m.layers) absolute.push_back(index *= l.eta);
        std::reverse(absolute.begin(), absolute.end());
        for (size_t i = 0; i < flipped.size(); ++i) flipped[i].eta = absolute[i] / (i ? absolute[i - 1] : 1.0);
        if (!std::isfinite(flipped.front().thickness))
            throw InputError("field '" + r.field("flip") + "': a stack with a semi-infinite layer has no other side");
        m.layers = std::move(flipped);
    }
    if (m.model == "multipole") {
        m.max_dipole_pairs = r.integer("max_dipole_pairs");
        m.max_pairs_field = r.field("max_dipole_pairs");
    }
    if (m.model == "mc") {
        m.photons = r.integer("photons");
        m.seed = uint64_t(r.integer("seed"));
        m.mc_r_max = r.number("mc_r_max_mm");
    }
    if ((m.model == "dipole" || m.model == "multipole") && m.layers.size() != 1)
        throw InputError("field '" + r.field("model") + "': the " + m.model +
                         " is one slab's; a stack of layers needs \"layered\" or \"mc\"");
    if (m.model == "mc" && std::isinf(m.layers.back().thickness))
        for (int c = 0; c < 3; ++c)
            if (!(m.layers.back().sigma_a[size_t(c)] > 0))
                throw InputError("field '" + r.field("model") +
                                 "': Monte Carlo in an absorption-free half-space never ends; give sigma_a > 0");
    for (const optics::LayerSpec& l : m.layers)
        if (l.roughness > 0 && l.roughness < 0.05)
            throw InputError("field '" + r.field("roughness") +
                             "': below 0.05 the lobe is too narrow for the rho_dt quadrature; give 0 (smooth) or more");
    r.finish();
    return m;
}

std::shared_ptr<const BuiltProfiles> build_profiles(const ProfileMaterial& m, const GatherSettings& g) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const BuiltProfiles>> cache;
    std::ostringstream k;
    k.precision(17);
    k << profile_key(m) << " | " << g.pattern << ' ' << g.samples << ' ' << g.table_size << ' ' << g.tail_fraction;
    const std::string key = k.str();
    std::lock_guard<std::mutex> lock(mutex);
    std::shared_ptr<const BuiltProfiles> built;
    if (auto it = cache.find(key); it != cache.end()) {
        auto again = std::make_shared<BuiltProfiles>(*it->second);
        again->build_ms = 0;
        again->source = "memory";
        built = again;
    } else {
        try {
            built = build(m, g, profile_key(m));
        } catch (const std::invalid_argument& e) {
            throw InputError("field 'material': its profile cannot be built: " + std::string(e.what()));
        }
        cache[key] = built;
    }
    std::ostringstream line;
    line.precision(3);
    line << m.model << " (" << m.layers.size() << (m.layers.size() == 1 ? " layer" : " layers") << "): "
         << built->source << ", " << std::fixed << built->build_ms << " ms";
    std::lock_guard<std::mutex> log_lock(log_mutex());
    build_log().push_back(line.str());
    return built;
}

std::vector<std::string> profile_build_log() {
    std::lock_guard<std::mutex> lock(log_mutex());
    return build_log();
}

}  // namespace st
