// param_sampler.h: scene settings drawn from a kind's declared space
// (scene/param_space.h), for the explorer (`shadertwin explore`).
//
// A case is a base scene plus a few assignments ("search.binary_steps" = 0,
// "triangles.3.colour" = [...]); the document a case renders is the base
// with them applied and then made consistent with the space (an object
// that became required is added with drawn required fields, fields that
// no longer apply are dropped, bounds taken from other fields are met).
// Draws depend on the seed and the case number only, never on time or
// thread count, so a case can be drawn again from its number.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/param_space.h"

namespace st {

// splitmix64: small, fast and the same on every platform (std::
// distributions are not).
class SampleRng {
public:
    explicit SampleRng(uint64_t seed) : state_(seed) {}
    uint64_t next();
    double uniform();                           // [0, 1)
    uint64_t below(uint64_t n);                 // [0, n), n > 0
    bool chance(double p) { return uniform() < p; }

private:
    uint64_t state_;
};

struct Assignment {
    std::string path;  // concrete: array indices as numbers
    nlohmann::json value;
    bool operator==(const Assignment&) const = default;
};

class ParamSampler {
public:
    explicit ParamSampler(const ParamSpace& space) : space_(space) {}

    // 1 to max_fields assignments to explorable fields that apply to `base`
    // (and to each other), each value drawn uniformly or, with probability
    // edge_share, from the domain's edges.
    std::vector<Assignment> draw(const nlohmann::json& base, SampleRng& rng, int max_fields,
                                 double edge_share = 0.5) const;
    // base + assignments, made consistent with the space (see above).
    // Draws for the fields it must add come from `rng`.
    nlohmann::json apply(const nlohmann::json& base, const std::vector<Assignment>& assignments,
                         SampleRng& rng) const;

    // Whether the field applies in `doc` (its `when` and every enclosing
    // object's hold, the enclosing array exists); `at` is its concrete path,
    // whose indices say which array entry a condition is read in (empty:
    // outside arrays).
    bool applies(const FieldSpec& f, const nlohmann::json& doc, const std::string& at = "") const;
    // One value of the field, its dependent bounds read from `doc` at `path`.
    nlohmann::json draw_value(const FieldSpec& f, const std::string& path, const nlohmann::json& doc,
                              SampleRng& rng, bool edge) const;

private:
    bool present_enough(const std::string& path, const nlohmann::json& doc) const;
    // The value at a concrete path, else the declared default, else null.
    nlohmann::json value_or_default(const nlohmann::json& doc, const std::string& path) const;
    const ParamSpace& space_;
};

// The fewest of `drawn` that still fail: drop one assignment at a time,
// keep the drop while `fails` holds, until no single drop does (a
// 1-minimal set; `fails(drawn)` is assumed).
std::vector<Assignment> shrink_assignments(std::vector<Assignment> drawn,
                                           const std::function<bool(const std::vector<Assignment>&)>& fails);

// Whether `entry` (an array entry of a scene) is a twin-only switch: an
// object whose "name" begins with "twin_", such as the uniform twin_naive
// that makes a twin write the GLSL as it stands so that a test can see the
// scene fail. The GLSL declares no such uniform, so any value but the
// scene's own breaks the twin by design; the explorer never draws one.
bool is_twin_switch(const nlohmann::json* entry);

// The value at a dotted concrete path, or null.
const nlohmann::json* json_at(const nlohmann::json& doc, const std::string& path);
// Sets it, creating objects on the way (not array entries).
void json_set(nlohmann::json& doc, const std::string& path, nlohmann::json value);

}  // namespace st
