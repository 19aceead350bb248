// param_space_test.cpp: every built-in kind's declared space is whole: the
// fields its declarations refer to exist, defaults and sampler hints lie in
// the domains, and each field's object is declared too.
#include "scene/param_space.h"

#include <gtest/gtest.h>

#include <algorithm>

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

}  // namespace
}  // namespace st
