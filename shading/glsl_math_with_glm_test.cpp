// glsl_math_with_glm_test.cpp: a twin that includes <glm/glm.hpp> first (as
// most C++ graphics code does, and as new-technique's skeletons do) still
// compiles against glsl_math.h and glsl_texture.h, and its GLSL names are
// ours, not glm's: glm declares pack*, mix, dot and the like for its own
// types, which argument-dependent lookup would otherwise find.
#include <glm/glm.hpp>

#include "shading/glsl_math.h"
#include "shading/glsl_texture.h"

#include <gtest/gtest.h>

namespace st {
namespace {

TEST(GlslMathWithGlm, GlslNamesResolveToTheTwinsBuiltins) {
    using namespace st::glsl;
    const glm::vec2 g2(0.25f, 0.75f);
    const glm::vec4 g4(0.1f, 0.2f, 0.3f, 0.4f);
    // One lane of each packing built-in equals the scalar form.
    const UInt packed = packUnorm2x16(Vec2(g2));
    EXPECT_EQ(packed[0], glsl::packUnorm2x16(g2));
    EXPECT_EQ(packUnorm4x8(Vec4(g4))[0], glsl::packUnorm4x8(g4));
    EXPECT_EQ(packHalf2x16(Vec2(g2))[0], glsl::packHalf2x16(g2));
    // Lanes: unqualified calls as a twin writes them.
    const Vec3 n = normalize(Vec3(Float(1.0f), Float(2.0f), Float(2.0f)));
    const Float d = dot(n, Vec3(Float(0.0f), Float(0.0f), Float(1.0f)));
    EXPECT_EQ(d[0], n.z[0]);
    const Float m = mix(Float(0.0f), Float(8.0f), Float(0.25f));
    EXPECT_EQ(m[0], 2.0f);
    // glm values through glsl:: (as the docs say to call them).
    EXPECT_EQ(glsl::dot(glm::vec3(1, 2, 3), glm::vec3(1, 1, 1)), 6.0f);
}

}  // namespace
}  // namespace st
