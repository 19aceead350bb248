// param_space_test.cpp: the declared spaces cover every built-in scene's
// fields, and the sampler draws inside them, deterministically.
#include "scene/param_space.h"

#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "scene/json_reader.h"
#include "scene/param_sampler.h"
#include "scene/scene.h"
#include "scene/scene_sources.h"

namespace st {
namespace {

nlohmann::json read(const std::string& path) {
    std::ifstream in(path);
    return parse_json(in, path);
}

// Every member of `node` at `path` must be declared (below opaque objects,
// the object's own reader decides).
void expect_declared(const ParamSpace& space, const nlohmann::json& node, const std::string& path,
                     const std::string& scene) {
    if (node.is_array()) {
        for (size_t i = 0; i < node.size(); ++i)
            if (node[i].is_object()) expect_declared(space, node[i], path + "." + std::to_string(i), scene);
        return;
    }
    if (!node.is_object()) return;
    for (const auto& [key, value] : node.items()) {
        const std::string p = path.empty() ? key : path + "." + key;
        const FieldSpec* f = space.find(ParamSpace::normalise(p));
        EXPECT_NE(f, nullptr) << scene << ": field " << p << " is not declared in kind " << space.kind();
        if (f && !f->opaque) expect_declared(space, value, p, scene);
    }
}

TEST(ParamSpace, DeclaresEveryFieldOfEveryBuiltInScene) {
    int checked = 0;
    for (const SceneEntry& e : SceneSources().entries()) {
        const nlohmann::json doc = read(e.path);
        const ParamSpace* space = kind_space(doc.value("kind", ""));
        if (!space) continue;
        expect_declared(*space, doc, "", e.name);
        ++checked;
    }
    EXPECT_GT(checked, 5);
}

TEST(ParamSpace, DomainsAreWellFormed) {
    for (const std::string& kind : spaced_kinds()) {
        const ParamSpace& s = *kind_space(kind);
        for (const FieldSpec& f : s.fields()) {
            if (f.type == FieldType::Number || f.type == FieldType::Integer || f.type == FieldType::Numbers) {
                EXPECT_LE(f.lo, f.hi) << kind << " " << f.path;
                EXPECT_TRUE(std::isfinite(f.lo) && std::isfinite(f.hi)) << kind << " " << f.path;
                if (f.fallback.is_number())
                    EXPECT_TRUE(f.fallback.get<double>() >= f.lo && f.fallback.get<double>() <= f.hi)
                        << kind << " " << f.path << " default outside its domain";
            }
            if (f.type == FieldType::Choice && f.fallback.is_string())
                EXPECT_NE(std::find(f.choices.begin(), f.choices.end(), f.fallback.get<std::string>()), f.choices.end())
                    << kind << " " << f.path;
            for (const std::string& other : {f.lo_field, f.hi_field, f.when_field})
                if (!other.empty()) EXPECT_NE(s.find(other), nullptr) << kind << " " << f.path << " names " << other;
        }
    }
}

TEST(ParamSampler, DrawsInsideTheDomainAndTheSameForTheSameSeed) {
    const ParamSpace& space = *kind_space("relief");
    const ParamSampler sampler(space);
    const nlohmann::json base = read(SceneSources().find("relief-absorption")->path);
    std::set<double> steps_seen;
    for (uint64_t seed = 0; seed < 3000; ++seed) {
        SampleRng a(seed), b(seed);
        const auto drawn = sampler.draw(base, a, 3);
        ASSERT_EQ(drawn, sampler.draw(base, b, 3));
        ASSERT_FALSE(drawn.empty());
        for (const Assignment& as : drawn) {
            const FieldSpec& f = space.at(as.path);
            ASSERT_TRUE(f.explore) << as.path;
            const auto check = [&](const nlohmann::json& v) {
                ASSERT_TRUE(v.is_number()) << as.path;
                const double x = v.get<double>();
                EXPECT_TRUE(x >= f.lo && x <= f.hi) << as.path << " = " << x;
                if (f.type == FieldType::Integer) EXPECT_TRUE(v.is_number_integer()) << as.path;
            };
            if (f.type == FieldType::Number || f.type == FieldType::Integer) check(as.value);
            if (f.type == FieldType::Numbers)
                for (const auto& x : as.value) check(x);
            if (f.type == FieldType::Choice)
                EXPECT_NE(std::find(f.choices.begin(), f.choices.end(), as.value.get<std::string>()), f.choices.end());
            if (as.path == "search.linear_steps") steps_seen.insert(as.value.get<double>());
        }
    }
    // Edge draws reach both bounds of a step count.
    EXPECT_TRUE(steps_seen.count(1));
    EXPECT_TRUE(steps_seen.count(128));  // the explorer's cap of 512
}

TEST(ParamSampler, ApplyKeepsTheDocumentConsistentWithTheSpace) {
    const ParamSampler sampler(*kind_space("relief"));
    const nlohmann::json base = read(SceneSources().find("relief-two-layer")->path);
    SampleRng rng(1);
    // A row without a medium drops the medium's objects.
    const nlohmann::json mapping = sampler.apply(base, {{"technique", "relief"}}, rng);
    EXPECT_FALSE(mapping.contains("liquid"));
    EXPECT_FALSE(mapping.contains("environment"));
    EXPECT_NO_THROW(load_scene_document("t", mapping, ""));
    // Absorption needs half distances: drawn, inside their domain.
    const nlohmann::json absorption = sampler.apply(base, {{"technique", "absorption"}}, rng);
    ASSERT_TRUE(absorption["liquid"].contains("half_distance"));
    EXPECT_NO_THROW(load_scene_document("t", absorption, ""));
    // A bound that is another field's value is met.
    const nlohmann::json radii = sampler.apply(base, {{"liquid.min_radius", 0.3}}, rng);
    EXPECT_GE(radii["liquid"].value("max_radius", 0.11), 0.3);
    EXPECT_NO_THROW(load_scene_document("t", radii, ""));
}

TEST(ParamSpace, ReadingAnUndeclaredFieldIsADefect) {
    ParamSpace s("test");
    s.integer("steps", 1, 8, 4, "");
    const nlohmann::json doc = {{"steps", 3}, {"other", 1}};
    JsonReader r(doc, "");
    r.bind(s);
    EXPECT_EQ(r.integer("steps"), 3);
    EXPECT_THROW(r.number("other"), std::logic_error);
    const nlohmann::json bad = {{"steps", 9}};
    JsonReader rb(bad, "");
    rb.bind(s);
    try {
        rb.integer("steps");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "field 'steps' is out of range [1, 8]");
    }
}

}  // namespace
}  // namespace st
