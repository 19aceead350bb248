// profile_quality.cpp: `quality: auto` for profile scenes (profile_quality.h).
#include "app/quality/profile_quality.h"

#include "app/quality/image_budget.h"

#include <algorithm>
#include <cmath>
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
    return read_quality_budget(document, "the cheapest model and sample count");
}

nlohmann::json with_choice(const nlohmann::json& document, const std::string& model, int samples) {
    nlohmann::json d = without_quality_fields(document);
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
            const ObjectError e = object_error(image, reference, choice.budget);
            c.over_budget = e.over_budget, c.p99 = e.p99, c.max = e.max;
            c.within = e.within();
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

// v2: the cache holds the whole record; v3: made only for a document that
// stands on its own (resolve_profile_quality).
std::string choice_key(const nlohmann::json& document) {
    return quality_choice_key("quality v3", document, quality_budget(document));
}

}  // namespace

nlohmann::json profile_choice_record(const QualityChoice& choice) {
    nlohmann::json r = {{"technique", "profile"},
                        {"budget", choice.budget},
                        {"reference", "the Monte Carlo profile gathered with " + std::to_string(kReferenceSamples) + " samples"},
                        {"setting", choice.model() + ", " + std::to_string(choice.samples()) + " samples"},
                        {"fields", {{"model", choice.model()}, {"samples", choice.samples()}}},
                        {"within_budget", choice.chosen >= 0},
                        {"candidates_tried", choice.tried.size()},
                        {"most_accurate_cpu_ms", choice.reference_ms}};
    if (choice.chosen >= 0) {
        const QualityCandidate& c = choice.tried[size_t(choice.chosen)];
        r["over_budget"] = c.over_budget;
        r["p99_8bit"] = c.p99;
        r["max_8bit"] = c.max;
        r["cpu_ms"] = c.frame_ms;
    } else {
        r["cpu_ms"] = choice.reference_ms;
    }
    return r;
}

void remember_quality_choice(const nlohmann::json& document, const QualityChoice& choice) {
    store_cached_record(choice_key(document), profile_choice_record(choice).dump());
}

nlohmann::json resolve_profile_quality(Backends& backends, const std::string& name, nlohmann::json& document) {
    if (const auto cached = load_cached_record(choice_key(document))) {
        const nlohmann::json record = nlohmann::json::parse(*cached, nullptr, false);
        if (record.is_object() && record.contains("fields") && record["fields"].is_object()) {
            const nlohmann::json& f = record["fields"];
            if (f.contains("model") && f["model"].is_string() && f.contains("samples") &&
                f["samples"].is_number_integer() && f["samples"].get<int>() > 0 &&
                f["samples"].get<int>() <= kMaxGatherSamples) {
                document = with_choice(document, f["model"].get<std::string>(), f["samples"].get<int>());
                return record;
            }
        }
    }
    // The scene as written first: a bad field the choice would overwrite is
    // refused, not replaced (quality_resolver.cpp does the same).
    load_scene_document(name, without_quality_fields(document), "");
    const QualityChoice choice = measure_quality(backends, name, document, 3);
    remember_quality_choice(document, choice);
    document = with_choice(document, choice.model(), choice.samples());
    return profile_choice_record(choice);
}

}  // namespace st
