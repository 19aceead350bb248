// thin_slab_quality.h: `quality: auto` for thin-slab scenes (issue 28):
// where Eq. 4-8 are evaluated. The candidates: per vertex in the vertex
// program (`vertex`), per vertex on the host (`host`), per fragment
// (`fragment`), in the order of the frame times `sweep thin-slab` measured
// at the flag mesh nearest the scene's (measured_costs.h; at equal times
// in that order). The first within the budget (image_budget.h) of the
// reference is chosen: the fragment variant with exact (double) arithmetic
// (thin_slab_exact.h). Per-vertex evaluation is
// close enough when the mesh is fine relative to how fast mu and mu0 change
// across it; on a coarse mesh, or with the light near the flag's plane, it
// is not. When not even the fragment variant meets the budget, it is used
// anyway (the most accurate) and the resolver says so. The Lambert baseline
// is no candidate: it is not the model.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/quality/image_budget.h"
#include "app/quality/measured_costs.h"

namespace st {

class TwinLibrary;

struct ThinSlabCandidate {
    std::string variant;
    ObjectError error;
    double sweep_ms = 0;  // what ordered it (measured_costs.h)
};

// What orders the variants: a variant's frame time on a flag of `quads`.
using ThinSlabCost = std::function<double(const std::string& variant, int quads)>;
inline double measured_thin_slab_cost(const std::string& variant, int quads) {
    return measured_costs::thin_slab_variant_ms(variant, double(quads));
}

// The variants in the order they are tried for a flag of `quads` quads,
// with the frame times that order them.
std::vector<std::pair<std::string, double>> thin_slab_cost_order(int quads, const ThinSlabCost& cost = measured_thin_slab_cost);

struct ThinSlabQualityChoice {
    std::string scene;
    double budget = kDefaultQualityBudget;
    int quads = 0;                         // the flag's, which picks the measured mesh
    std::vector<ThinSlabCandidate> tried;  // in the cost order, up to the choice
    int chosen = -1;                       // into tried; -1: none within, the fragment variant (the most accurate)
    double chosen_ms = 0, most_accurate_ms = 0;  // median CPU frames (the fragment variant's)
    std::string variant() const { return chosen < 0 ? "fragment" : tried[size_t(chosen)].variant; }
};

double thin_slab_quality_budget(const nlohmann::json& document);

// Renders the candidates on the CPU with `twins` (ThinSlabExactTwins),
// ordered by `cost` (the sweep passes the times it has just measured).
ThinSlabQualityChoice measure_thin_slab_quality(const TwinLibrary& twins, int threads, const std::string& name,
                                                const nlohmann::json& document, int frames,
                                                const ThinSlabCost& cost = measured_thin_slab_cost);

// The document with "variant" set and no "quality" fields.
nlohmann::json with_thin_slab_variant(const nlohmann::json& document, const std::string& variant);

nlohmann::json thin_slab_choice_record(const ThinSlabQualityChoice& choice);

}  // namespace st
