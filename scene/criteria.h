// criteria.h: what `compare` requires of a scene's CPU and GL images. A
// scene file may state its own (with the reasoning behind its bounds);
// otherwise the strict default applies.
#pragma once

#include <string>
#include <vector>

#include "image/compare.h"
#include "scene/json_reader.h"

namespace st {

struct Criteria {
    long coverage_mismatch = 0;
    int max_diff_8bit = 1;
    double max_rel_diff_float = 1e-5;
    double min_identical_fraction_8bit = 0.0;
    // Conformance scenes ask for 1: every pixel's float bits equal.
    double min_identical_fraction_float = 0.0;
    // "nonfinite": "identical" allows inf and NaN where both backends write
    // the same bits (a shader that divides by zero on purpose); by default
    // any non-finite channel fails.
    bool nonfinite_if_identical = false;
    std::string rationale;  // why these bounds (free text from the scene file)

    static Criteria read(JsonReader& scene);  // from the optional "criteria" object
    // Human-readable reasons the metrics fail; empty when they pass.
    std::vector<std::string> failures(const CompareMetrics& m, long coverage) const;
};

}  // namespace st
