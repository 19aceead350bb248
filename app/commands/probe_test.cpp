// probe_test.cpp: the probe command's rewrite of a fragment source: names
// in the order they first appear, the #define line skipped, and a probe
// run's prelude, renamed main and write of the stored value.
#include "app/commands/probe.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace st {

namespace {
const char* kSource = R"(#version 450 core
#ifndef ST_PROBE
#define ST_PROBE(name, value)
#endif
layout(location = 0) out vec4 colour;
void main() {
    float a = 1.0;
    ST_PROBE(a, a); ST_PROBE( b , vec2(a));
    for (int i = 0; i < 3; ++i) ST_PROBE(a, a + float(i));
    colour = vec4(a);
}
)";
}  // namespace

TEST(Probe, NamesInTheOrderTheyFirstAppear) {
    EXPECT_EQ(probe_names(kSource), (std::vector<std::string>{"a", "b"}));
    EXPECT_TRUE(probe_names("#version 450\nvoid main() {}\n").empty());
}

TEST(Probe, SourceWritesOnlyTheChosenProbe) {
    const std::string s = probe_source(kSource, {"a", "b"}, "b");
    EXPECT_EQ(s.rfind("#version 450 core\n", 0), 0u);  // still first
    EXPECT_NE(s.find("#define st_probe_b(v) st_probe_set(v)\n"), std::string::npos);
    EXPECT_NE(s.find("#define st_probe_a(v)\n"), std::string::npos);
    EXPECT_NE(s.find("#define main st_probe_main\n#line 2\n"), std::string::npos);
    EXPECT_NE(s.find("colour = st_probe_value;"), std::string::npos);
    // The only output, without a location, is location 0 (as public shaders write FragColor).
    EXPECT_NE(probe_source("#version 330 core\nout vec4 FragColor;\nvoid main() {}\n", {"a"}, "a").find("FragColor = st_probe_value;"),
              std::string::npos);
    // No vec4 colour to write to: two outputs without locations, a vec3, none.
    EXPECT_THROW(probe_source("#version 450\nout vec4 c;\nout vec4 d;\nvoid main() {}\n", {"a"}, "a"), std::runtime_error);
    EXPECT_THROW(probe_source("#version 450\nout vec3 c;\nvoid main() {}\n", {"a"}, "a"), std::runtime_error);
    EXPECT_THROW(probe_source("#version 450\nlayout(location = 1) out vec4 c;\nvoid main() {}\n", {"a"}, "a"), std::runtime_error);
}

}  // namespace st
