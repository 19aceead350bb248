// bindings_test.cpp: a twin reads uniforms by their GLSL names and types:
// the typed getters, get<T> for every mirrored type, an array's elements
// by GL's element names, bool set either way GL sets it, and a refusal
// naming the uniform that is missing or of another type.
#include "shading/program.h"

#include <gtest/gtest.h>

namespace st {
namespace {

// A uniform of `type` holding `values` (column-major for matrices).
Uniform make(const std::string& name, UniformType type, std::initializer_list<double> values) {
    Uniform u{name, type, {}};
    size_t i = 0;
    for (double v : values) u.value[i++] = v;
    return u;
}

TEST(Bindings, GetMirrorsEveryGlslType) {
    const glm::mat3 normal_matrix(1, 2, 3, 4, 5, 6, 7, 8, 9);
    const glm::mat2x3 skew(1, 2, 3, 4, 5, 6);
    const std::vector<Uniform> uniforms = {
        make("normalMatrix", UniformType::Mat3, {1, 2, 3, 4, 5, 6, 7, 8, 9}),
        make("skew", UniformType::Mat2x3, {1, 2, 3, 4, 5, 6}), make("mirrored", UniformType::Int, {1}),
        make("inverted", UniformType::UInt, {0}), make("count", UniformType::UVec2, {3, 4}),
        make("scale", UniformType::Double, {0.1}), make("lightPositions[0]", UniformType::Vec3, {1, 1, 1}),
        make("lightPositions[1]", UniformType::Vec3, {2, 2, 2}), make("lightPositions[2]", UniformType::Vec3, {3, 3, 3})};
    Bindings b;
    b.uniforms = &uniforms;
    EXPECT_EQ(b.get<glm::mat3>("normalMatrix"), normal_matrix);
    EXPECT_EQ(b.get<glm::mat2x3>("skew"), skew);
    EXPECT_TRUE(b.get<bool>("mirrored"));
    EXPECT_FALSE(b.get<bool>("inverted"));  // a bool set with glUniform1ui
    EXPECT_EQ(b.get<glm::uvec2>("count"), glm::uvec2(3u, 4u));
    EXPECT_EQ(b.get<double>("scale"), 0.1);
    const std::array<glm::vec3, 3> lights = b.array<glm::vec3, 3>("lightPositions");
    EXPECT_EQ(lights[2], glm::vec3(3.0f));
    // One element more than the scene sets: named.
    try {
        b.array<glm::vec3, 4>("lightPositions");
        FAIL() << "a missing element was read";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "uniform 'lightPositions[3]' is not set");
    }
    EXPECT_THROW(b.get<glm::mat4>("normalMatrix"), std::runtime_error);  // another type
}

}  // namespace
}  // namespace st
