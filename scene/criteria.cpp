// criteria.cpp: see criteria.h.
#include "scene/criteria.h"

#include <sstream>

namespace st {

Criteria Criteria::read(JsonReader& scene) {
    Criteria c;
    auto r = scene.object_if("criteria");
    if (!r) return c;
    c.coverage_mismatch = r->integer_or("coverage_mismatch", 0, 0, 1 << 30);
    c.max_diff_8bit = r->integer_or("max_diff_8bit", c.max_diff_8bit, 0, 255);
    c.max_rel_diff_float = r->number_or("max_rel_diff_float", c.max_rel_diff_float, 0, 1e30);
    c.min_identical_fraction_8bit = r->number_or("min_identical_fraction_8bit", 0.0, 0.0, 1.0);
    c.min_identical_fraction_float = r->number_or("min_identical_fraction_float", 0.0, 0.0, 1.0);
    const std::string nonfinite = r->choice_or("nonfinite", "none", {"none", "identical", "nan_any_payload"});
    c.nonfinite = nonfinite == "identical"         ? Nonfinite::Identical
                  : nonfinite == "nan_any_payload" ? Nonfinite::AnyNanPayload
                                                   : Nonfinite::None;
    c.condition_map = r->boolean_or("condition_map", false);
    c.min_within_1lsb_fraction = r->number_or("min_within_1lsb_fraction", c.min_within_1lsb_fraction, 0.0, 1.0);
    c.rationale = r->string_or("rationale", "");
    r->finish();
    return c;
}

std::vector<std::string> Criteria::failures(const CompareMetrics& m, long coverage, long over_1lsb,
                                           long explained) const {
    std::vector<std::string> out = failures(m, coverage);
    if (!condition_map) return out;
    // The 8-bit bound is the map's to decide: drop it, then check the map.
    std::erase_if(out, [](const std::string& f) { return f.rfind("max_diff_8bit ", 0) == 0; });
    const double pixels = double(m.width) * double(m.height);
    const double within = pixels > 0 ? 1.0 - double(over_1lsb) / pixels : 1.0;
    std::ostringstream s;
    if (within < min_within_1lsb_fraction) {
        s << "within_1lsb_fraction " << within << " (limit " << min_within_1lsb_fraction << ")";
        out.push_back(s.str());
    }
    if (explained < over_1lsb)
        out.push_back("pixels off by more than 1 LSB that the condition map does not explain: " +
                      std::to_string(over_1lsb - explained));
    return out;
}

std::vector<std::string> Criteria::failures(const CompareMetrics& m, long coverage) const {
    std::vector<std::string> out;
    auto fail = [&](const std::string& what, auto got, auto limit) {
        std::ostringstream s;
        s << what << " " << got << " (limit " << limit << ")";
        out.push_back(s.str());
    };
    // With "nan_any_payload", a NaN against a NaN of other bits is no difference.
    const bool any_nan = nonfinite == Nonfinite::AnyNanPayload;
    const double rel = any_nan ? m.max_rel_diff_float_any_nan : m.max_rel_diff_float;
    const double identical = any_nan ? m.identical_fraction_float_any_nan : m.identical_fraction_float;
    if (coverage > coverage_mismatch) fail("coverage_mismatch", coverage, coverage_mismatch);
    if (m.max_diff_8bit > max_diff_8bit) fail("max_diff_8bit", m.max_diff_8bit, max_diff_8bit);
    if (!(rel <= max_rel_diff_float)) fail("max_rel_diff_float", rel, max_rel_diff_float);
    if (m.identical_fraction_8bit < min_identical_fraction_8bit)
        fail("identical_fraction_8bit", m.identical_fraction_8bit, min_identical_fraction_8bit);
    if (identical < min_identical_fraction_float) fail("identical_fraction_float", identical, min_identical_fraction_float);
    if (nonfinite == Nonfinite::None) {
        if (m.nonfinite_a || m.nonfinite_b) fail("non-finite channels", m.nonfinite_a + m.nonfinite_b, 0);
    } else {
        const long differ = m.nonfinite_mismatch - (any_nan ? m.nan_payload_only : 0);
        if (differ) fail("non-finite channels that differ", differ, 0);
    }
    return out;
}

}  // namespace st
