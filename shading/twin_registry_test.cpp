// twin_registry_test.cpp: names are unique, lookups of unknown names are null.
#include "shading/twin_registry.h"

#include <gtest/gtest.h>

namespace st {
namespace {

class NoVertex final : public VertexTwin {
public:
    int varying_count() const override { return 0; }
    void run(const glm::vec4*, VertexOut&) const override {}
};

TEST(TwinRegistry, ANameIsTakenOnce) {
    TwinRegistry r;
    r.add_vertex("a", [] { return std::make_unique<NoVertex>(); });
    EXPECT_NE(r.make_vertex("a"), nullptr);
    EXPECT_EQ(r.make_vertex("b"), nullptr);
    EXPECT_EQ(r.make_fragment("a"), nullptr);
    try {
        r.add_vertex("a", [] { return std::make_unique<NoVertex>(); });
        FAIL() << "a second twin under one name was taken";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "vertex twin 'a' registered twice");
    }
    EXPECT_THROW(r.add_vertex("", [] { return std::make_unique<NoVertex>(); }), std::invalid_argument);
    EXPECT_THROW(r.add_fragment("f", nullptr), std::invalid_argument);
    EXPECT_EQ(r.vertex_names(), std::vector<std::string>{"a"});
}

}  // namespace
}  // namespace st
