// varying_interface_test.cpp: each way a pair of twins can hold other slots
// than its GLSL declares is refused with one line naming the variable and
// both sides' view; twins that name their slots pass against a shader
// without locations (GL links it by name), and twins without names pass
// against one with locations.
#include "app/interface/varying_interface.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"

namespace st {
namespace {

// A LearnOpenGL-style pair: no locations on the varyings or the output.
const char* kPbrVert = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec2 aTexCoords;
layout (location = 2) in vec3 aNormal;
out vec2 TexCoords;
out vec3 WorldPos;
out vec3 Normal;
void main() { TexCoords = aTexCoords; WorldPos = aPos; Normal = aNormal; gl_Position = vec4(aPos, 1.0); }
)";
const char* kPbrFrag = R"(#version 330 core
out vec4 FragColor;
in vec2 TexCoords;
in vec3 WorldPos;
in vec3 Normal;
void main() { FragColor = vec4(normalize(Normal) + WorldPos, TexCoords.x); }
)";
// The same with locations, a flat input and an interface block.
const char* kLocatedVert = R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 0) out vec2 uv;
layout(location = 1) flat out int material;
layout(location = 2) out Surface { vec3 normal; vec3 tangent; } surface;
void main() { uv = position.xy; material = 1; surface.normal = position.xyz; surface.tangent = position.zyx; gl_Position = position; }
)";
const char* kLocatedFrag = R"(#version 450
layout(location = 0) in vec2 uv;
layout(location = 1) flat in int material;
layout(location = 2) in Surface { vec3 normal; vec3 tangent; } surface;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(surface.normal * float(material), uv.x); }
)";

struct Vertex final : VertexTwin {
    int slots = 3;
    SlotNames names;
    int varying_count() const override { return slots; }
    void run(const glm::vec4*, VertexOut&) const override {}
    SlotNames output_names() const override { return names; }
};

struct Fragment final : FragmentTwin {
    uint32_t read = ~0u;
    Interpolations qualifiers{};
    SlotNames names;
    void shade(const FragmentLanes&, FragmentResult&) const override {}
    uint32_t inputs_read() const override { return read; }
    Interpolations interpolations() const override { return qualifiers; }
    SlotNames input_names() const override { return names; }
};

std::string refusal(const char* vert, const Vertex& vt, const char* frag, const Fragment& ft, int attributes = 3,
                    std::vector<std::string> names = {}) {
    VertexArray vertices;
    vertices.attribute_count = attributes;
    vertices.names = std::move(names);
    try {
        check_twin_varyings(parse_glsl_stage(vert, "shaders/pbr.vert"), vt, parse_glsl_stage(frag, "shaders/pbr.frag"), ft,
                            vertices);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(VaryingInterface, NamedSlotsAgainstAShaderWithoutLocations) {
    Vertex vt;
    vt.names = {"TexCoords", "WorldPos", "Normal"};
    Fragment ft;
    ft.names = vt.names;
    ft.read = reads(0, "x") | reads(1, "xyz") | reads(2, "xyz");
    EXPECT_EQ(refusal(kPbrVert, vt, kPbrFrag, ft), "");
    // An input the vertex shader does not write (GL's link would refuse it).
    const std::string renamed = std::string(kPbrVert).replace(std::string(kPbrVert).find("out vec3 Normal;"), 16,
                                                              "out vec3 Normals;");
    EXPECT_EQ(refusal(renamed.c_str(), vt, kPbrFrag, ft), "pbr.frag reads 'Normal', which pbr.vert does not write (its "
                                                          "outputs: TexCoords, WorldPos, Normals)");
    // A name the shader does not have.
    ft.names[2] = "Normals";
    EXPECT_EQ(refusal(kPbrVert, vt, kPbrFrag, ft), "the twin of pbr.frag names slot 2 'Normals', which pbr.frag does not "
                                             "declare as an input (its inputs: TexCoords, WorldPos, Normal)");
    // The two twins disagree on a slot.
    ft.names = {"TexCoords", "Normal", "WorldPos"};
    EXPECT_EQ(refusal(kPbrVert, vt, kPbrFrag, ft),
              "the twin of pbr.vert writes 'Normal' to slot 2, and the twin of pbr.frag reads it from slot 1");
    // A component past the declared type.
    ft.names = vt.names;
    ft.read |= reads(0, "xyz");
    EXPECT_EQ(refusal(kPbrVert, vt, kPbrFrag, ft), "the twin of pbr.frag reads component z of slot 0, 'TexCoords', a vec2 in pbr.frag");
    // An input the shader uses and the twin leaves out.
    ft.read = reads(0, "x") | reads(1, "xyz");
    EXPECT_EQ(refusal(kPbrVert, vt, kPbrFrag, ft), "pbr.frag uses input 'Normal' (slot 2), which the twin of pbr.frag's "
                                             "inputs_read() leaves out: it would read NaN");
}

TEST(VaryingInterface, ATwinWithoutNamesCannotPlaceInputsWithoutLocations) {
    Vertex vt;
    Fragment ft;
    EXPECT_EQ(refusal(kPbrVert, vt, kPbrFrag, ft), "pbr.frag uses input 'TexCoords' without a location, and the twin of "
                                             "pbr.frag names no slot for it (input_names())");
}

TEST(VaryingInterface, SlotsByLocation) {
    Vertex vt;
    vt.slots = 4;
    Fragment ft;
    ft.qualifiers[1] = Interpolation::Flat;
    ft.read = reads(0, "x") | reads(1, "x") | reads(2, "xyz");
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 1), "");
    // Block members take the block's locations in turn: Surface.normal is 2.
    ft.read = reads(0, "x") | reads(1, "x") | reads(3, "xyz");
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 1),
              "pbr.frag uses input 'Surface.normal' (slot 2), which the twin of pbr.frag's inputs_read() leaves out: it "
              "would read NaN");
    // A slot the shader declares nothing at.
    ft.read = reads(0, "x") | reads(1, "x") | reads(2, "xyz") | reads(5, "x");
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 1),
              "the twin of pbr.frag reads varying slot 5, where pbr.frag declares no input (its inputs: uv at 0, "
              "material at 1, Surface.normal at 2, Surface.tangent at 3)");
    // Named slots against explicit locations: the location wins.
    ft.read = reads(0, "x") | reads(1, "x") | reads(2, "xyz");
    ft.names = {"uv", "Surface.normal", "material"};
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 1),
              "the twin of pbr.frag holds 'Surface.normal' in slot 1; pbr.frag declares it at location 2");
}

TEST(VaryingInterface, QualifiersAttributesAndOutputs) {
    Vertex vt;
    vt.slots = 4;
    Fragment ft;
    ft.read = reads(0, "x") | reads(1, "x") | reads(2, "xyz");
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 1),
              "'material' is flat in pbr.frag, and the twin of pbr.frag's interpolations() has slot 1 smooth");
    ft.qualifiers[1] = Interpolation::Flat;
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 0),
              "pbr.vert reads input 'position' at location 0, and the draw gives 0 attributes");
    vt.slots = 2;
    EXPECT_EQ(refusal(kLocatedVert, vt, kLocatedFrag, ft, 1),
              "the twin of pbr.frag reads varying slot 2, and the twin of pbr.vert writes 2 slots");
    vt.slots = 4;
    const std::string two_outputs = std::string(kLocatedFrag).replace(std::string(kLocatedFrag).find("void main"), 0,
                                                                      "layout(location = 1) out vec4 bright;\n");
    EXPECT_EQ(refusal(kLocatedVert, vt, two_outputs.c_str(), ft, 1),
              "pbr.frag declares outputs colour at 0, bright at 1, and the pass draws into 1 target (location 0)");
    // A pass with two targets: the shader's two outputs fit, the twin's one does not.
    VertexArray one;
    one.attribute_count = 1;
    try {
        check_twin_varyings(parse_glsl_stage(kLocatedVert, "shaders/pbr.vert"), vt,
                            parse_glsl_stage(two_outputs, "shaders/pbr.frag"), ft, one, 2);
        ADD_FAILURE() << "a twin writing one output passed for two";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "the twin of pbr.frag writes 1 output, and pbr.frag declares 2");
    }
    // Several outputs need their locations.
    const std::string unlocated = std::string(kPbrFrag).replace(std::string(kPbrFrag).find("in vec2 TexCoords;"), 0,
                                                                "out vec4 Bright;\n");
    vt.names = {"TexCoords", "WorldPos", "Normal"};
    ft.names = vt.names;
    EXPECT_EQ(refusal(kPbrVert, vt, unlocated.c_str(), ft, 3),
              "pbr.frag declares outputs FragColor, Bright, 'FragColor' without a location: with several outputs give "
              "each its layout(location = N), or bind them by name (DrawCall::output_names)");
    // Bound by name, as glBindFragDataLocation does.
    VertexArray three;
    three.attribute_count = 3;
    const auto bound = [&](std::vector<std::string> names) {
        try {
            check_twin_varyings(parse_glsl_stage(kPbrVert, "shaders/pbr.vert"), vt,
                                parse_glsl_stage(unlocated, "shaders/pbr.frag"), ft, three, 2, names);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(bound({"Bright", "FragColor"}), "the twin of pbr.frag writes 1 output, and pbr.frag declares 2");
    EXPECT_EQ(bound({"Bright", "FragColour"}), "the draw binds output 'FragColour' to location 1, and pbr.frag declares no "
                                               "such output (its outputs: FragColor, Bright at 0)");
}

// Attributes by name: a vertex shader without locations on its inputs.
TEST(VaryingInterface, AttributesByName) {
    const std::string unlocated = std::string(kPbrVert).replace(std::string(kPbrVert).find("layout (location = 0) in vec3 aPos;"),
                                                                 35, "in vec3 aPos;");
    Vertex vt;
    vt.names = {"TexCoords", "WorldPos", "Normal"};
    Fragment ft;
    ft.names = vt.names;
    EXPECT_EQ(refusal(unlocated.c_str(), vt, kPbrFrag, ft, 3),
              "pbr.vert uses input 'aPos' without a location, and the draw does not name its attributes (VertexArray::names)");
    EXPECT_EQ(refusal(unlocated.c_str(), vt, kPbrFrag, ft, 3, {"aPos", "aTexCoords", "aNormal"}), "");
    // aPos may sit in any column; the others keep their locations.
    EXPECT_EQ(refusal(unlocated.c_str(), vt, kPbrFrag, ft, 3, {"aNormal", "aTexCoords", "aPos"}),
              "the draw gives 'aNormal' as attribute 0; pbr.vert declares it at location 2");
    EXPECT_EQ(refusal(unlocated.c_str(), vt, kPbrFrag, ft, 3, {"aPoss", "aTexCoords", "aNormal"}),
              "the draw names attribute 0 'aPoss', which pbr.vert does not declare as an input (its inputs: aPos, "
              "aTexCoords at 1, aNormal at 2)");
    EXPECT_EQ(refusal(unlocated.c_str(), vt, kPbrFrag, ft, 2, {"aPos", "aTexCoords"}),
              "pbr.vert uses input 'aNormal', which no attribute of the draw names");
    EXPECT_EQ(refusal(unlocated.c_str(), vt, kPbrFrag, ft, 3, {"aPos"}), "the draw names 1 vertex attributes and gives 3");
}

}  // namespace
}  // namespace st
