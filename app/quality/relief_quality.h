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
// 1. the search: candidates in a fixed cost order, the first within the
//    budget wins, the other knobs at their most accurate. Cost units: one
//    per linear step (for a count scaled by the view angle, the count at the
//    scene's angle), two per binary step, none for the secant step; fitted
//    to `sweep relief`'s frame times (docs/relief-sweep/relief-sweep.csv:
//    a binary step costs 1.6 to 2.7 linear steps from 30 to 85 degrees,
//    the secant step nothing measurable), so the order is the measured one
//    and the same on every machine;
// 2. planar reflections (two-layer rows) when they keep the image within
//    the budget (1.4 times faster than searched ones on Table 1's scene);
// 3. the fewest light crossings, 1, 2, 4 or 8, within the budget
//    (occlusion and absorption).
// Errors decide, never a timing, so a scene always resolves the same way.
// The most accurate setting (512 / 16 / secant) is the last candidate:
// where only it meets the budget it is chosen; where not even it does, it
// is used anyway, and the resolver says so in one line.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/quality/image_budget.h"

namespace st {

class TwinLibrary;

struct ReliefSetting {
    int linear_steps = 512, min_linear_steps = 0, binary_steps = 16;
    bool secant = true;
    bool planar = false;    // reflections.planar (two-layer rows)
    int max_crossings = 16; // liquid.max_crossings (occlusion, absorption)
    std::string label() const;  // "16 / 6 / secant", "mix(64,8) / 4 / secant, planar, 2 crossings"
};

struct ReliefCandidate {
    ReliefSetting setting;
    double cost = 0;  // cost units (above)
    ObjectError error;
};

struct ReliefQualityChoice {
    std::string scene, technique;
    double budget = kDefaultQualityBudget;
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

// Renders a relief scene's candidates on the CPU with `twins` (which must
// hold ReliefSweepTwins' exact program, for the record's comparison with
// the exact image), `frames` timed frames for the chosen and the most
// accurate setting.
ReliefQualityChoice measure_relief_quality(const TwinLibrary& twins, int threads, const std::string& name,
                                           const nlohmann::json& document, int frames);

// The document with the setting written in and no "quality" fields.
nlohmann::json with_relief_setting(const nlohmann::json& document, const ReliefSetting& setting);

// What compare, render and the report show of a choice.
nlohmann::json relief_choice_record(const ReliefQualityChoice& choice);

}  // namespace st
