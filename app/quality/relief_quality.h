// relief_quality.h: `quality: auto` for relief scenes (issue 28): the
// cheapest search, reflections and light crossings whose image stays within
// the error budget of the scene's reference (image_budget.h).
//
// The reference is the scene with every search replaced by the exact first
// crossing of the height map as the sampler reads it (relief_exact.h,
// reference/relief_sampled_crossing.h): what every search converges to, so
// that a candidate's error is its own, with the other knobs at their most
// accurate (searched reflections, 16 light crossings). Not the crossing of
// the bilinear surface in exact arithmetic (relief_intersection.h): the
// 8-bit filter the shader reads through moves the surface by up to half a
// step, and against that image no search keeps 99 % of the pixels within
// one step, the most accurate included (4.2 % over on relief-mapping at 45
// degrees), so no setting could be chosen by it; for relief mapping the
// record gives the chosen and the most accurate setting's error against it,
// so that floor shows. Normal mapping has nothing to choose.
//
// The choice, one knob at a time, each step checked against the reference
// on the whole image:
// 1. the search: candidates (relief_search_settings, the most accurate
//    among them, the slowest in every measured order) cheapest first, the
//    first within the budget wins, the other knobs at their most accurate.
//    Cheapest by the frame time `sweep relief` measured for the setting at
//    the scene's view angle (measured_costs.h: relief mapping's scene, for
//    every row), so the order is measured, and the same on every machine;
// 2. planar reflections (two-layer rows) when they keep the image within
//    the budget (1.4 times faster than searched ones on Table 1's scene);
// 3. the fewest light crossings, 1, 2, 4 or 8, within the budget
//    (occlusion and absorption).
// Errors decide, never a timing, so a scene always resolves the same way.
// The most accurate setting (512 / 16 / secant) is a candidate: where only
// it meets the budget it is chosen; where not even it does, it is used
// anyway, and the resolver says so in one line.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/quality/image_budget.h"
#include "app/quality/measured_costs.h"

namespace st {

class ReliefSweepTwins;

struct ReliefSetting {
    int linear_steps = 512, min_linear_steps = 0, binary_steps = 16;
    bool secant = true;
    bool planar = false;    // reflections.planar (two-layer rows)
    int max_crossings = 16; // liquid.max_crossings (occlusion, absorption)
    std::string label() const;  // "16 / 6 / secant", "mix(64,8) / 4 / secant, planar, 2 crossings"
};

struct ReliefCandidate {
    ReliefSetting setting;
    double cost = 0;  // ms, measured (above)
    ObjectError error;
};

// Every search setting auto may choose for a row (`technique`), the most
// accurate (ReliefSetting{}) among them; `sweep relief` times them all.
std::vector<ReliefSetting> relief_search_settings(const std::string& technique);

// What orders the search candidates: a setting's frame time at a view angle.
using ReliefCost = std::function<double(const ReliefSetting&, double angle_deg)>;

struct ReliefQualityChoice {
    std::string scene, technique;
    double budget = kDefaultQualityBudget;
    double angle_deg = 45;                // the view angle the costs were read at
    std::string reference;                // what the candidates were measured against
    std::vector<ReliefCandidate> tried;   // in the order tried
    int chosen = -1;                      // into tried; -1: the most accurate setting
    bool nothing_to_choose = false;       // normal mapping
    double chosen_ms = 0, most_accurate_ms = 0;  // median CPU frames
    ObjectError most_accurate_error;              // the most accurate setting against the reference
    // Relief mapping: the chosen and the most accurate image against the
    // image shaded at the bilinear surface's crossing (the 8-bit floor).
    bool have_exact = false;
    ObjectError exact_chosen, exact_most_accurate;
    ReliefSetting setting() const { return chosen < 0 ? ReliefSetting{} : tried[size_t(chosen)].setting; }
};

// InputError for a bad "quality" or "quality_budget".
double relief_quality_budget(const nlohmann::json& document);

// Renders a relief scene's candidates and its exact images on the CPU with
// `twins`, `frames` timed frames for the chosen and the most
// accurate setting; `cost` orders the candidates (the sweep passes the times
// it has just measured).
ReliefQualityChoice measure_relief_quality(
    const ReliefSweepTwins& twins, int threads, const std::string& name, const nlohmann::json& document, int frames,
    const ReliefCost& cost = [](const ReliefSetting& s, double angle) { return measured_costs::relief_search_ms(s, angle); });

// The document with the setting written in and no "quality" fields.
nlohmann::json with_relief_setting(const nlohmann::json& document, const ReliefSetting& setting);

// What compare, render and the report show of a choice.
nlohmann::json relief_choice_record(const ReliefQualityChoice& choice);

}  // namespace st
