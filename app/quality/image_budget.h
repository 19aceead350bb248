// image_budget.h: the error budget `quality: auto` holds every technique to
// (issues 11 and 28): a candidate's image against its scene's reference,
// over the object's pixels (those not black in either image), in 8-bit
// steps of the worst RGB channel. A candidate is within the budget when at
// most kOverBudgetShare of those pixels are more than `budget` steps off.
// Also what every technique's choice shares: reading the budget, timing a
// candidate, and the key a choice is cached under.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "image/image.h"

namespace st {

inline constexpr double kDefaultQualityBudget = 1.0;  // 8-bit steps
inline constexpr double kOverBudgetShare = 0.01;

struct ObjectError {
    double over_budget = 0;  // share of the object's pixels beyond the budget
    double p99 = 0, max = 0;  // 8-bit steps, worst channel
    bool within() const { return over_budget <= kOverBudgetShare; }
};

ObjectError object_error(const Image& candidate, const Image& reference, double budget);

// The document's "quality" (which must be "auto", `what` saying what it
// chooses) and "quality_budget" (8-bit steps in [0.5, 64], default 1);
// InputError naming the field otherwise.
double read_quality_budget(const nlohmann::json& document, const std::string& what);

// The median CPU frame of `frames` runs of a prepared frame (prepare and
// read-back excluded, as the backends time a frame).
class CpuRenderer;
struct Frame;
double median_frame_ms(CpuRenderer& renderer, const Frame& frame, int frames);

// The document without "quality" and "quality_budget".
nlohmann::json without_quality_fields(const nlohmann::json& document);

// The profile cache's key of a choice (scene/profile_cache.h): the rule and
// its version, the budget, and the scene as written without its quality
// fields (nlohmann dumps objects with sorted keys).
std::string quality_choice_key(const std::string& rule, const nlohmann::json& document, double budget);

}  // namespace st
