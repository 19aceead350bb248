// thin_slab_quality.h: `quality: auto` for thin-slab scenes (issue 28):
// where Eq. 4-8 are evaluated. The candidates, in a fixed cost order: per
// vertex in the vertex program (`vertex`), per vertex on the host (`host`),
// per fragment (`fragment`); measured on this project's bench, the two
// per-vertex variants run a frame in the same time within noise (313 and
// 311 fps on the thin-slab scenes, docs/performance.md) and the fragment
// one takes 1.6 times as long (190 fps). The first within the budget
// (image_budget.h) of the reference is chosen: the fragment variant with
// exact (double) arithmetic (thin_slab_exact.h). Per-vertex evaluation is
// close enough when the mesh is fine relative to how fast mu and mu0 change
// across it; on a coarse mesh, or with the light near the flag's plane, it
// is not. When not even the fragment variant meets the budget, it is used
// anyway (the most accurate) and the resolver says so. The Lambert baseline
// is no candidate: it is not the model.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/quality/image_budget.h"

namespace st {

class TwinLibrary;

struct ThinSlabCandidate {
    std::string variant;
    ObjectError error;
};

struct ThinSlabQualityChoice {
    std::string scene;
    double budget = kDefaultQualityBudget;
    std::vector<ThinSlabCandidate> tried;  // in the cost order, up to the choice
    int chosen = -1;                       // into tried; -1: none within, the fragment variant
    double chosen_ms = 0, most_accurate_ms = 0;  // median CPU frames (the fragment variant's)
    std::string variant() const { return chosen < 0 ? "fragment" : tried[size_t(chosen)].variant; }
};

double thin_slab_quality_budget(const nlohmann::json& document);

// Renders the candidates on the CPU with `twins` (ThinSlabExactTwins).
ThinSlabQualityChoice measure_thin_slab_quality(const TwinLibrary& twins, int threads, const std::string& name,
                                                const nlohmann::json& document, int frames);

// The document with "variant" set and no "quality" fields.
nlohmann::json with_thin_slab_variant(const nlohmann::json& document, const std::string& variant);

nlohmann::json thin_slab_choice_record(const ThinSlabQualityChoice& choice);

}  // namespace st
