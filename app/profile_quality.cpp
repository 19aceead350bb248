// profile_quality.cpp: `quality: auto` (profile_quality.h).
#include "app/profile_quality.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>

#include "app/median.h"
#include "app/tool_data.h"
#include "app/backends.h"
#include "app/commands.h"
#include "image/unorm8.h"
#include "scene/input_error.h"
#include "scene/json_reader.h"
#include "scene/profile_cache.h"
#include "scene/profile_material.h"
#include "scene/scene.h"
#include "scene/scene_spaces.h"

namespace st {

namespace {

// The sample counts tried, fewest first; the reference takes kReferenceSamples.
constexpr int kSampleCounts[] = {8, 16, 32, 64, 128, 256, 512};
// The models, cheapest profile build first. Monte Carlo is also the
// reference's: tried last, with fewer samples, for a scene no diffusion
// model serves within the budget.
constexpr const char* kModels[] = {"dipole", "multipole", "layered", "mc"};
// The reference's Monte Carlo bins reach this many of the material's
// longest diffusion lengths 1 / sigma_tr (e^-7 < 1e-3), at least the
// default 20 mm: a profile cut short would darken the reference itself.
constexpr double kReferenceReachLengths = 7.0;
constexpr double kMaxReferenceReachMm = 500.0;

// The material's fields that belong to one model only.
void set_model(nlohmann::json& material, const std::string& model) {
    material["model"] = model;
    if (model != "mc")
        for (const char* key : {"photons", "seed", "mc_r_max_mm"}) material.erase(key);
    if (model != "multipole") material.erase("max_dipole_pairs");
}

struct ObjectError {
    double over_budget = 0, p99 = 0, max = 0;
};

// Per pixel of the object (either image not black), the worst channel's
// 8-bit difference.
ObjectError image_error(const Image& a, const Image& reference, double budget) {
    std::vector<double> d;
    for (size_t p = 0; p + 3 < reference.rgba.size(); p += 4) {
        bool object = false;
        double worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const uint8_t x = to_unorm8(a.rgba[p + c]), r = to_unorm8(reference.rgba[p + c]);
            object |= x != 0 || r != 0;
            worst = std::max(worst, std::abs(double(x) - double(r)));
        }
        if (object) d.push_back(worst);
    }
    ObjectError e;
    if (d.empty()) return e;
    e.over_budget = double(std::count_if(d.begin(), d.end(), [&](double x) { return x > budget; })) / double(d.size());
    std::sort(d.begin(), d.end());
    e.p99 = d[std::min(d.size() - 1, size_t(0.99 * double(d.size())))];
    e.max = d.back();
    return e;
}

std::string last_build_line(size_t before) {
    const std::vector<std::string> log = profile_build_log();
    return log.size() > before ? log.back() : std::string("(built before in this process)");
}

}  // namespace

double reference_reach_mm(const nlohmann::json& material) {
    JsonReader r(material, "material");
    r.bind(profile_space());
    const ProfileMaterial m = read_profile_material(r);
    double longest = 0;
    for (const optics::LayerSpec& l : m.layers)
        for (size_t c = 0; c < 3; ++c) {
            const double sa = l.sigma_a[c], ss = l.sigma_s[c] * (1 - l.g);
            const double sigma_tr = std::sqrt(3 * sa * (sa + ss));
            longest = std::max(longest, sigma_tr > 0 ? 1 / sigma_tr : kMaxReferenceReachMm);
        }
    return std::clamp(kReferenceReachLengths * longest, ProfileMaterial{}.mc_r_max, kMaxReferenceReachMm);
}

double quality_budget(const nlohmann::json& document) {
    const auto kind = document.find("kind");
    if (kind == document.end() || !kind->is_string() || kind->get<std::string>() != "profile")
        throw InputError("field 'quality': \"auto\" chooses a profile scene's model and samples; this scene is no "
                         "profile scene");
    const nlohmann::json& q = document.at("quality");
    if (!q.is_string() || q.get<std::string>() != "auto")
        throw InputError("field 'quality' must be \"auto\" (the cheapest model and sample count within the budget)");
    if (!document.contains("quality_budget")) return kDefaultQualityBudget;
    const nlohmann::json& b = document.at("quality_budget");
    if (!b.is_number() || !(b.get<double>() >= 0.5 && b.get<double>() <= 64.0))
        throw InputError("field 'quality_budget' must be a number of 8-bit steps in [0.5, 64]");
    return b.get<double>();
}

nlohmann::json with_choice(const nlohmann::json& document, const std::string& model, int samples) {
    nlohmann::json d = document;
    d.erase("quality");
    d.erase("quality_budget");
    if (!d.contains("material") || !d["material"].is_object())
        throw InputError("field 'quality': a profile scene's material is needed to choose its model");
    set_model(d["material"], model);
    if (!d.contains("gather")) d["gather"] = nlohmann::json::object();
    if (!d["gather"].is_object()) throw InputError("field 'gather' must be an object");
    d["gather"]["samples"] = samples;
    return d;
}

QualityChoice measure_quality(Backends& backends, const std::string& name, const nlohmann::json& document,
                              int frames) {
    QualityChoice choice;
    choice.scene = name;
    choice.budget = quality_budget(document);
    auto timed = [&](const Frame& frame, Image* image) {
        std::vector<double> ms;
        for (int f = 0; f < frames; ++f) {
            Rendered r = backends.render(Backend::Cpu, frame);
            ms.push_back(r.ms);
            if (f == 0 && image) *image = std::move(r.image);
        }
        return median(ms);
    };
    size_t log_before = profile_build_log().size();
    nlohmann::json reference_document = with_choice(document, "mc", kReferenceSamples);
    nlohmann::json& material = reference_document["material"];
    if (!material.contains("mc_r_max_mm")) material["mc_r_max_mm"] = reference_reach_mm(material);
    choice.reference_reach_mm = material["mc_r_max_mm"].get<double>();
    const Scene reference_scene = load_scene_document(name, reference_document, "");
    choice.reference_build = last_build_line(log_before);
    Image reference;
    choice.reference_ms = timed(reference_scene.frame, &reference);

    int best_samples = kSampleCounts[std::size(kSampleCounts) - 1] + 1;  // fewer than this may still win
    for (const char* model : kModels) {
        // Monte Carlo, whose profile takes seconds to build where the others
        // take milliseconds, only when no diffusion model meets the budget.
        if (std::string(model) == "mc" && choice.chosen >= 0) break;
        for (int samples : kSampleCounts) {
            if (samples >= best_samples) break;  // an earlier model is as cheap or cheaper here
            log_before = profile_build_log().size();
            nlohmann::json candidate = with_choice(document, model, samples);
            if (std::string(model) == "mc") candidate["material"] = material;  // the reference's profile
            QualityCandidate c;
            c.model = model;
            c.samples = samples;
            Scene scene;
            try {
                scene = load_scene_document(name, candidate, "");
            } catch (const InputError& e) {
                // The dipole and the multipole are one slab's (a stack has
                // neither), and a model's profile may not fall off within
                // reach: the model does not apply. The reference loaded, so
                // the scene itself is sound.
                c.not_applicable = e.what();
                choice.tried.push_back(c);
                break;
            }
            c.build_source = last_build_line(log_before);
            Image image;
            c.frame_ms = timed(scene.frame, &image);
            const ObjectError e = image_error(image, reference, choice.budget);
            c.over_budget = e.over_budget, c.p99 = e.p99, c.max = e.max;
            c.within = e.over_budget <= kOverBudgetShare;
            choice.tried.push_back(c);
            if (c.within) {
                best_samples = samples;
                if (choice.chosen < 0 || samples < choice.tried[size_t(choice.chosen)].samples)
                    choice.chosen = int(choice.tried.size()) - 1;
                break;
            }
        }
    }
    return choice;
}

namespace {

// Everything a choice depends on: the scene as written without its quality
// fields (nlohmann dumps objects with sorted keys), the budget, this rule's
// version.
std::string choice_key(const nlohmann::json& document) {
    nlohmann::json base = document;
    base.erase("quality");
    base.erase("quality_budget");
    std::ostringstream key;
    key.precision(17);
    key << "quality v1 budget " << quality_budget(document) << ' ' << base.dump();
    return key.str();
}

}  // namespace

void remember_quality_choice(const nlohmann::json& document, const QualityChoice& choice) {
    store_cached_record(choice_key(document), choice.model() + " " + std::to_string(choice.samples()));
}

void install_quality_resolver(int threads, GlPlatform gl_platform) {
    set_quality_resolver([threads, gl_platform](const std::string& name, nlohmann::json& document) {
        if (const auto cached = load_cached_record(choice_key(document))) {
            std::istringstream in(*cached);
            std::string model;
            int samples = 0;
            if (in >> model >> samples && samples > 0 && samples <= kMaxGatherSamples) {
                document = with_choice(document, model, samples);
                return;
            }
        }
        static std::mutex mutex;
        static std::unique_ptr<Backends> backends;
        std::lock_guard<std::mutex> lock(mutex);
        if (!backends) backends = std::make_unique<Backends>(threads, gl_platform, glsl_roots());
        const QualityChoice choice = measure_quality(*backends, name, document, 3);
        remember_quality_choice(document, choice);
        document = with_choice(document, choice.model(), choice.samples());
    });
}

}  // namespace st
