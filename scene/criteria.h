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
    // the same bits (a shader that divides by zero on purpose);
    // "nan_any_payload" also lets a NaN match a NaN of other bits, the
    // bound where two NaNs meet in one operation (which one comes out is the
    // operand order LLVM emitted, which a twin cannot know): such channels
    // are counted (nan_payload_only) and shown white in the heat map. By
    // default any non-finite channel fails.
    enum class Nonfinite { None, Identical, AnyNanPayload };
    Nonfinite nonfinite = Nonfinite::None;
    std::string rationale;  // why these bounds (free text from the scene file)
    // Search scenes (issue 10): the CPU pipeline also renders the scene
    // with each search's ray perturbed by one ULP either way and marks the
    // pixels whose result then moves by more than 1 LSB (the condition
    // map). max_diff_8bit then bounds only the pixels the map does not
    // mark: a pixel off by more than 1 LSB that the map does not explain
    // fails, and at least min_within_1lsb_fraction of the pixels must be
    // within 1 LSB.
    bool condition_map = false;
    double min_within_1lsb_fraction = 0.995;

    static Criteria read(JsonReader& scene);  // from the optional "criteria" object
    // Human-readable reasons the metrics fail; empty when they pass.
    std::vector<std::string> failures(const CompareMetrics& m, long coverage) const;
    // With the condition map: pixels off by more than 1 LSB, and how many
    // of them the map marks.
    std::vector<std::string> failures(const CompareMetrics& m, long coverage, long over_1lsb, long explained) const;
};

}  // namespace st
