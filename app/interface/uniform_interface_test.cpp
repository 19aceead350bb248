// uniform_interface_test.cpp: each way a draw's uniforms can miss what its
// GLSL declares is refused with one line naming the uniform and both sides'
// view, and a draw that gives the program exactly what it declares (arrays,
// arrays of structs, a block, bool, mat3, samplers) passes.
#include "app/interface/uniform_interface.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "scene/uniform_values.h"

namespace st {
namespace {

const char* kVert = R"(#version 330 core
layout (location = 0) in vec3 aPos;
out vec3 WorldPos;
uniform mat4 projection;
uniform mat3 normalMatrix;
layout(std140) uniform Matrices { mat4 view; vec4 tint; } matrices;
void main() { WorldPos = normalMatrix * aPos; gl_Position = projection * matrices.view * vec4(aPos, 1.0); }
)";

const char* kFrag = R"(#version 330 core
out vec4 FragColor;
in vec3 WorldPos;
struct Light { vec3 position; float power; };
uniform vec3 lightPositions[4];
uniform Light lights[2];
uniform bool mirrored;
uniform sampler2D albedoMap;
uniform samplerCube environment;
void main() { FragColor = vec4(lightPositions[1] + lights[0].position, 1.0); }
)";

struct Fixture {
    GlslStage vs = parse_glsl_stage(kVert, "shaders/pbr.vert");
    GlslStage fs = parse_glsl_stage(kFrag, "shaders/pbr.frag");
    DrawCall draw;

    Fixture() {
        draw.uniforms = {uniform("projection", glm::mat4(1.0f)), uniform("normalMatrix", glm::mat3(1.0f)),
                         uniform("Matrices.view", glm::mat4(1.0f)), uniform("Matrices.tint", glm::vec4(1.0f)),
                         int_uniform("mirrored", 1)};
        for (int i = 0; i < 4; ++i) draw.uniforms.push_back(uniform("lightPositions[" + std::to_string(i) + "]", glm::vec3(float(i))));
        for (int i = 0; i < 2; ++i) {
            draw.uniforms.push_back(uniform("lights[" + std::to_string(i) + "].position", glm::vec3(1.0f)));
            draw.uniforms.push_back(uniform("lights[" + std::to_string(i) + "].power", 2.0f));
        }
        Texture albedo, environment;
        albedo.sampler = "albedoMap";
        environment.sampler = "environment";
        environment.cube = true;
        draw.textures = {albedo, environment};
    }
    // The message check_draw_uniforms refuses with, or "" when it passes.
    std::string refusal(const ActiveUniforms* active = nullptr) const {
        try {
            check_draw_uniforms(draw, vs, fs, active);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    }
};

TEST(UniformInterface, ADrawGivingWhatTheProgramDeclaresPasses) {
    Fixture f;
    EXPECT_EQ(f.refusal(), "");
    // GL's name for element 0 of an array is the array's name too.
    f.draw.uniforms[5].name = "lightPositions";
    EXPECT_EQ(f.refusal(), "");
    // A twin-only switch is no GLSL uniform.
    f.draw.uniforms.push_back(int_uniform("twin_naive", 1));
    EXPECT_EQ(f.refusal(), "");
}

TEST(UniformInterface, AnUndeclaredUniformIsNamedWithBothFiles) {
    Fixture f;
    f.draw.uniforms.push_back(uniform("camPoss", glm::vec3(0.0f)));
    EXPECT_EQ(f.refusal(), "the scene sets uniform 'camPoss', which neither pbr.vert nor pbr.frag declares "
                           "(a typo? a uniform only the twin reads is named twin_*)");
}

TEST(UniformInterface, AnIndexOrMemberTheDeclarationLacks) {
    Fixture f;
    f.draw.uniforms.push_back(uniform("lightPositions[4]", glm::vec3(0.0f)));
    EXPECT_EQ(f.refusal(), "uniform 'lightPositions[4]': lightPositions is vec3[4] in pbr.frag (indices 0 to 3)");
    f.draw.uniforms.back() = uniform("lights[1].colour", glm::vec3(0.0f));
    EXPECT_EQ(f.refusal(), "uniform 'lights[1].colour': struct Light (pbr.frag) has no member 'colour'");
    f.draw.uniforms.back() = uniform("Matrices.model", glm::mat4(1.0f));
    EXPECT_EQ(f.refusal(), "'Matrices.model': uniform block Matrices (pbr.vert) has no such member");
    f.draw.uniforms.back() = uniform("mirrored[0]", 1.0f);
    EXPECT_EQ(f.refusal(), "uniform 'mirrored[0]': mirrored is a bool in pbr.frag, not an array");
}

TEST(UniformInterface, AValueOfAnotherTypeNamesBothTypes) {
    Fixture f;
    f.draw.uniforms[1] = uniform("normalMatrix", glm::mat4(1.0f));  // what glm's conversion used to make of a mat3
    EXPECT_EQ(f.refusal(), "uniform 'normalMatrix' is a mat3 in pbr.vert, and the scene sets a mat4");
    f.draw.uniforms[1] = uniform("normalMatrix", glm::mat3(1.0f));
    f.draw.uniforms[4] = uniform("mirrored", 1.0f);
    EXPECT_EQ(f.refusal(), "uniform 'mirrored' is a bool in pbr.frag, and the scene sets a float");
    f.draw.uniforms[4] = uint_uniform("mirrored", 1u);  // glUniform1ui sets a bool too
    EXPECT_EQ(f.refusal(), "");
    f.draw.uniforms.push_back(int_uniform("albedoMap", 0));
    EXPECT_EQ(f.refusal(), "uniform 'albedoMap' is a sampler2D in pbr.frag: bind a texture to it, not a value");
}

TEST(UniformInterface, AUniformSetTwice) {
    Fixture f;
    f.draw.uniforms.push_back(uniform("projection", glm::mat4(2.0f)));
    EXPECT_EQ(f.refusal(), "uniform 'projection' is set twice in one draw");
}

TEST(UniformInterface, TexturesAgainstTheSamplers) {
    Fixture f;
    f.draw.textures[0].sampler = "albedo_map";
    EXPECT_EQ(f.refusal(), "a texture is bound to sampler 'albedo_map', which neither pbr.vert nor pbr.frag "
                           "declares as a sampler");
    f.draw.textures[0].sampler = "albedoMap";
    f.draw.textures[1].cube = false;
    EXPECT_EQ(f.refusal(), "sampler 'environment' is a samplerCube in pbr.frag, and the scene binds a 2D texture to it");
}

TEST(UniformInterface, AnActiveUniformNeverSet) {
    Fixture f;
    // As GL reports them: an array once with its size, struct arrays member by member.
    ActiveUniforms active = {{"projection", 1}, {"lightPositions[0]", 4}, {"lights[0].position", 1}, {"albedoMap", 1},
                             {"gl_DepthRange.near", 1}};
    EXPECT_EQ(f.refusal(&active), "");
    f.draw.uniforms.erase(f.draw.uniforms.begin() + 7);  // lightPositions[2]
    EXPECT_EQ(f.refusal(&active), "uniform 'lightPositions[2]' (vec3 in pbr.frag, active in the program) is never set "
                                  "by the scene: GL would read 0");
    Fixture g;
    g.draw.textures.erase(g.draw.textures.begin());
    EXPECT_EQ(g.refusal(&active), "sampler 'albedoMap' (sampler2D in pbr.frag, active in the program) has no texture "
                                  "bound: GL would sample unit 0");
    // Declared but optimised away (not active): nothing to set.
    Fixture h;
    h.draw.uniforms.erase(h.draw.uniforms.begin() + 4);  // mirrored
    EXPECT_EQ(h.refusal(&active), "");
}

}  // namespace
}  // namespace st
