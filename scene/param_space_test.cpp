// param_space_test.cpp: every built-in kind's declared space is whole: the
// fields its declarations refer to exist, defaults and sampler hints lie in
// the domains, and each field's object is declared too; every field of
// every built-in scene is declared; a reader refuses what its space does.
#include "scene/param_space.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "scene/input_error.h"
#include "scene/json_reader.h"
#include "scene/scene_sources.h"
#include "scene/scene_spaces.h"

namespace st {
namespace {

bool numeric(const FieldSpec& f) {
    return f.type == FieldType::Number || f.type == FieldType::Integer || f.type == FieldType::Numbers;
}

TEST(ParamSpace, EveryBuiltInKindHasOne) {
    const std::vector<std::string> kinds = spaced_kinds();
    for (const char* kind : {"conformance", "profile", "relief", "thin-slab", "triangles"}) {
        EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end()) << kind;
    }
}

TEST(ParamSpace, DeclarationsAreWhole) {
    for (const std::string& kind : spaced_kinds()) {
        const ParamSpace& s = *kind_space(kind);
        for (const FieldSpec& f : s.fields()) {
            SCOPED_TRACE(kind + ": " + f.path);
            for (const std::string* ref : {&f.lo_field, &f.hi_field, &f.when_field}) {
                if (!ref->empty()) {
                    EXPECT_NE(s.find(*ref), nullptr) << *ref;
                }
            }
            if (const FieldSpec* w = f.when_field.empty() ? nullptr : s.find(f.when_field)) {
                for (const std::string& v : f.when_values) {
                    EXPECT_NE(std::find(w->choices.begin(), w->choices.end(), v), w->choices.end()) << v;
                }
            }
            // Its object ("a.b[].c" lies in "a.b").
            if (const size_t dot = f.path.rfind('.'); dot != std::string::npos) {
                std::string parent = f.path.substr(0, dot);
                if (parent.ends_with("[]")) parent.resize(parent.size() - 2);
                const FieldSpec* p = s.find(parent);
                ASSERT_NE(p, nullptr) << parent;
                EXPECT_EQ(p->type, FieldType::Object);
            }
            if (numeric(f)) {
                EXPECT_LE(f.lo, f.hi);
                EXPECT_LE(f.draw_lo, f.draw_hi);
                EXPECT_GE(f.draw_lo, f.lo);
                EXPECT_LE(f.draw_hi, f.hi);
                EXPECT_TRUE(!f.log_scale || f.draw_lo > 0);
                for (double e : f.edges) {
                    EXPECT_TRUE(e >= f.lo && e <= f.hi) << e;
                }
                EXPECT_TRUE(f.explore_hi == 0 || (f.explore_hi >= f.lo && f.explore_hi <= f.hi));
                if (f.fallback.is_number()) {
                    EXPECT_TRUE(f.fallback.get<double>() >= f.lo && f.fallback.get<double>() <= f.hi);
                }
                if (f.fallback.is_array()) {
                    EXPECT_TRUE(f.fallback.size() >= f.min_len && f.fallback.size() <= f.max_len);
                    for (const auto& v : f.fallback) {
                        EXPECT_TRUE(v.get<double>() >= f.lo && v.get<double>() <= f.hi);
                    }
                }
            }
            if (f.type == FieldType::Choice && f.fallback.is_string()) {
                EXPECT_NE(std::find(f.choices.begin(), f.choices.end(), f.fallback.get<std::string>()), f.choices.end());
            }
            if (f.type == FieldType::Object && f.max_len) {
                EXPECT_LE(f.min_len, f.max_len);
                EXPECT_TRUE(f.explore_hi == 0 || f.explore_hi <= double(f.max_len));
            }
        }
        EXPECT_FALSE(s.markdown().empty());
    }
}

// The triangle list's rows are a triangle's three corners.
TEST(ParamSpace, TriangleCorners) {
    for (const char* kind : {"triangles", "conformance"}) {
        const ParamSpace& s = *kind_space(kind);
        for (const char* path : {"triangles[].positions", "triangles[].colours", "triangles[].uvs"}) {
            EXPECT_EQ(s.at(path).rows, 3u) << kind << " " << path;
        }
    }
    EXPECT_EQ(kind_space("conformance")->at("passes.0.triangles.7.uvs").path, "passes[].triangles[].uvs");
}

nlohmann::json read_scene_file(const std::string& path) {
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
        const nlohmann::json doc = read_scene_file(e.path);
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
