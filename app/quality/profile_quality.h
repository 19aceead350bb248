// profile_quality.h: "model no more than a scene needs" for diffusion-profile
// scenes (issue 11). `quality: auto` asks for the cheapest profile model and
// the fewest gather samples whose image stays within an error budget of the
// scene's reference: its material's Monte Carlo profile (the physics' ground
// truth) gathered with kReferenceSamples samples, on the CPU.
//
// The candidates are the diffusion models, dipole, multipole and
// layered, at 8 to 512 samples. Cost, measured and reported: a frame's time
// grows with the sample count and does not depend on the model (the gather
// reads its tables the same way whatever built them); the models differ in
// their profile's build time (dipole < multipole < layered, milliseconds,
// each built once per material). So the candidates are tried fewest samples
// first and the cheaper model first at equal samples, and the first within
// the budget is the choice: measured errors decide, never a noisy timing, so
// the same scene always resolves the same way. When no diffusion model meets
// the budget, the Monte Carlo profile itself (seconds to build, once) is
// tried with fewer samples than the reference; when that fails too, the
// reference's own settings are the answer. The budget: at most 1 % of the
// object's pixels more than `quality_budget` 8-bit steps (default 1) off the
// reference in any channel.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/quality/image_budget.h"

namespace st {

class Backends;

inline constexpr int kReferenceSamples = 1024;

struct QualityCandidate {
    std::string model;
    int samples = 0;
    double frame_ms = 0;     // median CPU frame
    double build_ms = 0;     // the profile's build in this process (0: built or cached before)
    std::string build_source;
    double over_budget = 0;  // share of the object's pixels beyond the budget
    double p99 = 0, max = 0; // 8-bit steps, the object's pixels, worst channel
    bool within = false;
    std::string not_applicable;  // why the model does not apply (then nothing else is set)
};

struct QualityChoice {
    std::string scene;
    double budget = kDefaultQualityBudget;
    double reference_ms = 0;            // median CPU frame of the reference
    std::string reference_build;          // the Monte Carlo profile's build-log line
    double reference_reach_mm = 0;        // its bins' reach
    std::vector<QualityCandidate> tried;  // in the order tried
    int chosen = -1;                      // into tried; -1: none within budget, the reference's settings
    std::string model() const { return chosen < 0 ? "mc" : tried[size_t(chosen)].model; }
    int samples() const { return chosen < 0 ? kReferenceSamples : tried[size_t(chosen)].samples; }
};

// The document's "quality_budget" (or the default); InputError for a bad
// "quality" or budget, or a scene of another kind.
double quality_budget(const nlohmann::json& document);

// Renders the candidates of a profile scene's document (its "quality"
// fields ignored) and the reference, `frames` timed frames each.
QualityChoice measure_quality(Backends& backends, const std::string& name, const nlohmann::json& document,
                              int frames);

// How far a Monte Carlo reference's radial bins reach for a material (its
// JSON object): 7 diffusion lengths 1 / sigma_tr of its most penetrating
// channel and layer, at least the default 20 mm, at most 500 mm.
double reference_reach_mm(const nlohmann::json& material);

// The document with the choice written in: material.model, gather.samples,
// and no "quality" fields.
nlohmann::json with_choice(const nlohmann::json& document, const std::string& model, int samples);

// What compare, render and the report show of a choice.
nlohmann::json profile_choice_record(const QualityChoice& choice);

// Keeps a measured choice in the profile cache, for the resolver below.
void remember_quality_choice(const nlohmann::json& document, const QualityChoice& choice);

// `quality: auto` of a profile scene's document: the choice from the profile
// cache (scene/profile_cache.h) or measured and kept there, written into
// the document; returns its record.
nlohmann::json resolve_profile_quality(Backends& backends, const std::string& name, nlohmann::json& document);

}  // namespace st
