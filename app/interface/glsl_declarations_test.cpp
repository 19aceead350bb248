// glsl_declarations_test.cpp: the declarations of shaders written as people
// write them (a learnopengl-style parallax pair: no output locations,
// interface blocks, a struct array sized by a #define, comments holding
// braces), and every refusal naming the file and the line; then the
// skeleton's files for that pair: every uniform bound and read, every
// varying in its slot.
#include "app/interface/glsl_declarations.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/new_technique/skeleton_files.h"
#include "scene/input_error.h"

namespace st::skeleton {
namespace {

const char* kVert = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
layout (location = 3) in vec3 aTangent;

out VS_OUT {
    vec3 FragPos;
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} vs_out;

uniform mat4 projection, view;
uniform mat4 model;
uniform vec3 viewPos;

void main()
{
    vs_out.FragPos = vec3(model * vec4(aPos, 1.0));
    vs_out.TexCoords = aTexCoords;
    vec3 T = normalize(mat3(model) * aTangent);
    vec3 N = normalize(mat3(model) * aNormal);
    mat3 TBN = transpose(mat3(T, cross(N, T), N));
    vs_out.TangentViewPos = TBN * viewPos;
    vs_out.TangentFragPos = TBN * vs_out.FragPos;
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
)";

const char* kFrag = R"(#version 330 core
#define NUM_LIGHTS 2
out vec4 FragColor;

in VS_OUT {
    vec3 FragPos;
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentFragPos;
} fs_in;

struct Light {
    vec3 colour;   // { not a brace that counts }
    float power;
};
/* a block comment: uniform vec3 ignored; { */
uniform sampler2D diffuseMap;
uniform sampler2D depthMap;
uniform float heightScale;
uniform Light lights[NUM_LIGHTS];
uniform bool flip;
const int kSteps = 8;
uniform float weights[kSteps];

vec2 ParallaxMapping(vec2 texCoords, vec3 viewDir)
{
    float layerDepth = 1.0 / float(kSteps);
    float currentLayerDepth = 0.0;
    vec2 deltaTexCoords = viewDir.xy / viewDir.z * heightScale / float(kSteps);
    float currentDepthMapValue = texture(depthMap, texCoords).r;
    while (currentLayerDepth < currentDepthMapValue) {
        texCoords -= deltaTexCoords;
        currentDepthMapValue = texture(depthMap, texCoords).r;
        currentLayerDepth += layerDepth;
    }
    return texCoords;
}

void main()
{
    vec3 viewDir = normalize(fs_in.TangentViewPos - fs_in.TangentFragPos);
    vec2 texCoords = ParallaxMapping(fs_in.TexCoords, viewDir);
    vec3 colour = texture(diffuseMap, texCoords).rgb * lights[0].colour * weights[1];
    FragColor = vec4(pow(colour, vec3(1.0 / 2.2)), 1.0);
}
)";

TEST(GlslDeclarations, ReadsAShaderAsPeopleWriteIt) {
    const GlslStage v = parse_glsl_stage(kVert, "pom.vs");
    EXPECT_EQ(v.version, "330 core");
    ASSERT_EQ(v.inputs.size(), 4u);
    EXPECT_EQ(v.inputs[2].name, "aTexCoords");
    EXPECT_EQ(v.inputs[2].type, "vec2");
    EXPECT_EQ(v.inputs[2].location, 2);
    ASSERT_EQ(v.blocks.size(), 1u);
    EXPECT_EQ(v.blocks[0].storage, "out");
    EXPECT_EQ(v.blocks[0].instance, "vs_out");
    EXPECT_EQ(v.blocks[0].members.size(), 4u);
    ASSERT_EQ(v.uniforms.size(), 4u);  // projection, view (one declaration), model, viewPos
    EXPECT_EQ(v.uniforms[1].name, "view");
    EXPECT_EQ(v.uniforms[1].type, "mat4");
    ASSERT_NE(v.function("main"), nullptr);
    EXPECT_NE(v.function("main")->body.find("gl_Position = projection * view * model"), std::string::npos);

    const GlslStage f = parse_glsl_stage(kFrag, "pom.fs");
    ASSERT_EQ(f.outputs.size(), 1u);
    EXPECT_EQ(f.outputs[0].location, -1);
    ASSERT_EQ(f.structs.size(), 1u);
    EXPECT_EQ(f.structs[0].members.size(), 2u);
    ASSERT_EQ(f.uniforms.size(), 6u);
    EXPECT_EQ(f.uniforms[3].name, "lights");
    EXPECT_EQ(f.uniforms[3].array_size, 2);  // NUM_LIGHTS
    EXPECT_EQ(f.uniforms[5].array_size, 8);  // const int kSteps
    ASSERT_EQ(f.functions.size(), 2u);
    EXPECT_EQ(f.functions[0].name, "ParallaxMapping");
    EXPECT_EQ(f.functions[0].parameters, "vec2 texCoords, vec3 viewDir");
    EXPECT_EQ(f.functions[0].line, 25);
}

TEST(GlslDeclarations, RefusesWhatItCannotPlaceNamingTheLine) {
    const auto refusal = [](const std::string& source) {
        try {
            parse_glsl_stage(source, "x.frag");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(taken)");
    };
    EXPECT_EQ(refusal("#version 450\nattribute vec4 p;\nvoid main() {}\n"),
              "x.frag:2: 'attribute' is GLSL 1.x: write in and out (#version 330 or later)");
    EXPECT_EQ(refusal("#version 450\nuniform float w[N];\nvoid main() {}\n"),
              "x.frag:2: array size 'N' is not a whole number, a #define or a const int");
    EXPECT_EQ(refusal("#version 450\n/* open\nvoid main() {}\n"), "x.frag:2: a comment that never ends");
    EXPECT_EQ(refusal("#version 450\nuniform float a;\n"), "x.frag: no main()");
    EXPECT_EQ(refusal("#include \"common.glsl\"\nvoid main() {}\n"),
              "x.frag:1: #include is not GLSL 4.50 core: paste the included file in");
    EXPECT_EQ(refusal("#version 450\nvoid main() {\n"), "x.frag:2: '{' never closed");
    EXPECT_EQ(refusal("#version 450\nbuffer B { float x; };\nvoid main() {}\n").find("x.frag:2:"), 0u);
}

std::string file_of(const std::vector<ProjectFile>& files, const std::string& path) {
    for (const ProjectFile& f : files)
        if (f.path == path) return f.text;
    ADD_FAILURE() << "no " << path;
    return "";
}

TEST(SkeletonFiles, BindsReadsAndPlacesEverythingTheShadersDeclare) {
    const GlslStage v = parse_glsl_stage(kVert, "pom.vs"), f = parse_glsl_stage(kFrag, "pom.fs");
    const std::vector<ProjectFile> files = skeleton_files("pom", v, kVert, f, kFrag);
    EXPECT_EQ(file_of(files, "glsl/pom.vert"), kVert);
    const std::string header = file_of(files, "kernels/pom.h");
    EXPECT_NE(header.find("struct Light {\n    glm::vec3 colour{};\n    float power{};\n};"), std::string::npos) << header;
    EXPECT_NE(header.find("std::array<Light, 2> lights_{};"), std::string::npos);
    EXPECT_NE(header.find("const st::Sampler2D* depthMap_ = nullptr;"), std::string::npos);
    EXPECT_NE(header.find("int varying_count() const override { return 4; }"), std::string::npos);
    const std::string frag = file_of(files, "kernels/pom_frag.cpp");
    // Block members take slots in order; the fragment's find them by block and name.
    EXPECT_NE(frag.find("constexpr int fs_in_TexCoords = 1;"), std::string::npos) << frag;
    EXPECT_NE(frag.find("constexpr int fs_in_TangentFragPos = 3;"), std::string::npos);
    EXPECT_NE(frag.find("st::reads(fs_in_FragPos, \"xyz\") | st::reads(fs_in_TexCoords, \"xy\")"), std::string::npos);
    EXPECT_NE(frag.find("lights_[size_t(i1)].colour = b.get_vec3(std::string(std::string(\"lights\") + \"[\" + "
                        "std::to_string(i1) + \"]\") + \".colour\");"),
              std::string::npos) << frag;
    EXPECT_NE(frag.find("flip_ = b.get_bool(\"flip\");"), std::string::npos);
    EXPECT_NE(frag.find("// vec2 ParallaxMapping(vec2 texCoords, vec3 viewDir) {"), std::string::npos);
    EXPECT_NE(frag.find("//     while (currentLayerDepth < currentDepthMapValue) {"), std::string::npos);
    const std::string vert = file_of(files, "kernels/pom_vert.cpp");
    EXPECT_NE(vert.find("constexpr int aTangent = 3;"), std::string::npos);
    EXPECT_NE(vert.find("constexpr int vs_out_TangentViewPos = 2;"), std::string::npos);
    const std::string scene = file_of(files, "kernels/pom_scene.cpp");
    EXPECT_NE(scene.find("st::read_texture_field(scene, \"depthMap\", \"depthMap\", budget)"), std::string::npos);
    EXPECT_NE(scene.find("st::read_uniform_field(scene, \"weights\", \"float\", 8, draw.uniforms);"), std::string::npos);
    EXPECT_NE(scene.find("std::vector<st::JsonReader> items0 = scene.objects(\"lights\", 2, 2);"), std::string::npos) << scene;
    EXPECT_NE(scene.find("draw.vertices.data.push_back({x, y, 0.0f, 1.0f});  // attribute 0 (vec3 aPos): position"),
              std::string::npos) << scene;
    // Each column names its input, so that GL binds it by name.
    EXPECT_NE(scene.find("draw.vertices.names = {\"aPos\", \"aNormal\", \"aTexCoords\", \"aTangent\"};"),
              std::string::npos) << scene;
    // The first scene has a value for every uniform, one of each shape.
    const nlohmann::json first = nlohmann::json::parse(file_of(files, "scenes/pom-first.json"));
    for (const char* u : {"projection", "view", "model", "viewPos", "diffuseMap", "depthMap", "heightScale", "lights",
                          "flip", "weights"})
        EXPECT_TRUE(first.contains(u)) << u;
    EXPECT_EQ(first["lights"].size(), 2u);
    EXPECT_EQ(first["projection"], "identity");
    EXPECT_EQ(first["diffuseMap"]["pattern"], "noise");
}

// Uniform blocks: a block without an instance name gives uniforms of their
// own; one with an instance is a struct of the block's type, whose members
// GL names "Block.member"; non-square matrices are uniforms like any.
TEST(SkeletonFiles, UniformBlocksAndNonSquareMatrices) {
    const std::string v = "#version 450\nlayout(location = 0) in vec4 p;\n"
                          "layout(std140) uniform Matrices { mat4 projection; mat4 view; };\n"
                          "void main() { gl_Position = projection * view * p; }\n";
    const std::string f = "#version 450\nout vec4 c;\nlayout(std140) uniform Light { vec3 colour; float power; } light;\n"
                          "uniform mat2x3 skew;\nvoid main() { c = vec4(light.colour * light.power + skew[0], 1.0); }\n";
    const std::vector<ProjectFile> files =
        skeleton_files("ubo", parse_glsl_stage(v, "u.vert"), v, parse_glsl_stage(f, "u.frag"), f);
    const std::string header = file_of(files, "kernels/ubo.h");
    EXPECT_NE(header.find("struct Light {\n    glm::vec3 colour{};\n    float power{};\n};"), std::string::npos) << header;
    EXPECT_NE(header.find("Light light_{};"), std::string::npos);
    EXPECT_NE(header.find("glm::mat4 projection_{};"), std::string::npos);
    EXPECT_NE(header.find("glm::mat2x3 skew_{};"), std::string::npos);
    const std::string frag = file_of(files, "kernels/ubo_frag.cpp");
    EXPECT_NE(frag.find("light_.colour = b.get_vec3(std::string(\"Light\") + \".colour\");"), std::string::npos) << frag;
    EXPECT_NE(frag.find("skew_ = b.get_mat2x3(\"skew\");"), std::string::npos);
    const std::string scene = file_of(files, "kernels/ubo_scene.cpp");
    EXPECT_NE(scene.find("st::JsonReader fields0 = scene.object(\"Light\");"), std::string::npos) << scene;
    EXPECT_NE(scene.find("st::read_uniform_field(fields0, \"colour\", \"vec3\", 0, draw.uniforms, std::string(\"Light\") + \".colour\");"),
              std::string::npos) << scene;
    EXPECT_NE(scene.find("st::read_uniform_field(scene, \"projection\", \"mat4\", 0, draw.uniforms);"), std::string::npos);
    const nlohmann::json first = nlohmann::json::parse(file_of(files, "scenes/ubo-first.json"));
    EXPECT_EQ(first["Light"]["power"], 0.5);
    EXPECT_EQ(first["skew"], "identity");
    EXPECT_EQ(first["view"], "identity");
}

// Interpolation qualifiers come from the fragment inputs; int and uint
// varyings travel as their bits in a flat slot.
TEST(SkeletonFiles, FlatNoPerspectiveAndIntegerVaryings) {
    const std::string v = "#version 450\nlayout(location = 0) in vec4 p;\nflat out ivec2 cell;\n"
                          "noperspective out vec3 screen;\nout uint tag;\nout float fade;\n"
                          "void main() { gl_Position = p; cell = ivec2(1); screen = p.xyz; tag = 7u; fade = p.w; }\n";
    const std::string f = "#version 450\nflat in ivec2 cell;\nnoperspective in vec3 screen;\nflat in uint tag;\n"
                          "centroid in float fade;\nout vec4 c;\nvoid main() { c = vec4(screen, float(cell.x + int(tag)) * fade); }\n";
    const std::vector<ProjectFile> files =
        skeleton_files("q", parse_glsl_stage(v, "q.vert"), v, parse_glsl_stage(f, "q.frag"), f);
    EXPECT_NE(file_of(files, "kernels/q.h").find("st::Interpolations interpolations() const override;"), std::string::npos);
    const std::string frag = file_of(files, "kernels/q_frag.cpp");
    EXPECT_NE(frag.find("    q[cell] = st::Interpolation::Flat;  // flat in ivec2 cell\n"
                        "    q[screen] = st::Interpolation::NoPerspective;  // noperspective in vec3 screen\n"
                        "    q[tag] = st::Interpolation::Flat;  // flat in uint tag\n    return q;"),
              std::string::npos) << frag;
    EXPECT_EQ(frag.find("q[fade]"), std::string::npos);  // centroid: smooth on a single-sampled target
    EXPECT_NE(frag.find("cell  ->  floatBitsToInt(frag.varying(cell).xy());"), std::string::npos);
    EXPECT_NE(frag.find("tag  ->  floatBitsToUint(frag.varying(tag).x);"), std::string::npos);
    EXPECT_NE(frag.find("st::reads(cell, \"xy\") | st::reads(screen, \"xyz\") | st::reads(tag, \"x\")"), std::string::npos);
    const std::string vert = file_of(files, "kernels/q_vert.cpp");
    EXPECT_NE(vert.find("cell = v  ->  out.varyings[cell] = glm::vec4(intBitsToFloat(v), ...)"), std::string::npos) << vert;
    EXPECT_NE(vert.find("tag = v  ->  out.varyings[tag] = glm::vec4(uintBitsToFloat(v), 0, 0, 0)"), std::string::npos);
}

TEST(SkeletonFiles, RefusesAnInterfaceTwinsCannotHave) {
    const auto refusal = [](const std::string& vert, const std::string& frag) {
        try {
            skeleton_files("t", parse_glsl_stage(vert, "t.vert"), vert, parse_glsl_stage(frag, "t.frag"), frag);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(taken)");
    };
    const std::string v = "#version 450\nlayout(location = 0) in vec4 p;\nout vec2 uv;\nvoid main() {}\n";
    const std::string fr = "#version 450\nin vec2 uv;\nout vec4 c;\nvoid main() {}\n";
    EXPECT_EQ(refusal(v, fr), "(taken)");
    // An input without a location takes the next free column (bound by name).
    EXPECT_EQ(refusal("#version 450\nin vec4 p;\nout vec2 uv;\nvoid main() {}\n", fr), "(taken)");
    EXPECT_EQ(refusal(v, "#version 450\nin vec2 st;\nout vec4 c;\nvoid main() {}\n"),
              "t.frag:2: input 'st' has no vertex output of its name");
    // Several outputs without locations: bound by name, in declaration order.
    EXPECT_EQ(refusal(v, "#version 450\nin vec2 uv;\nout vec4 c;\nout vec4 d;\nvoid main() {}\n"), "(taken)");
    EXPECT_EQ(refusal(v, "#version 450\nin vec2 uv;\nlayout(location = 0) out vec4 c;\nlayout(location = 2) out vec3 d;\nvoid main() {}\n"),
              "t.frag:4: output 'd' at location 2: the outputs' locations must be 0 to 1");
    // Several outputs with their locations, of any float type: main() returns one Vec4 each.
    EXPECT_EQ(refusal(v, "#version 450\nin vec2 uv;\nlayout(location = 1) out vec3 d;\nlayout(location = 0) out vec4 c;\nvoid main() {}\n"),
              "(taken)");
    EXPECT_EQ(refusal(v, "#version 450\nin vec2 uv;\nout vec4 c;\nlayout(std140) uniform M { mat4 m; } ms[2];\nvoid main() {}\n"),
              "t.frag:4: an arrayed uniform block ('M'): not modelled");
    EXPECT_EQ(refusal(v, "#version 450\nin vec2 uv;\nout vec4 c;\nuniform sampler3D vol;\nvoid main() {}\n").substr(0, 34),
              "t.frag:4: uniform sampler3D vol: s");
    EXPECT_EQ(refusal("#version 450\nlayout(location = 0) in vec4 p;\nout mat3 basis;\nvoid main() {}\n", fr).substr(0, 37),
              "t.vert:3: output mat3 basis: varyings");
    const std::string id_out = "#version 450\nlayout(location = 0) in vec4 p;\nflat out int id;\nvoid main() {}\n";
    EXPECT_EQ(refusal(id_out, "#version 450\nin int id;\nout vec4 c;\nvoid main() {}\n"),
              "t.frag:2: input int id: an integer input must be qualified flat (GLSL 4.50, 4.5)");
    EXPECT_EQ(refusal(id_out, "#version 450\nflat in uint id;\nout vec4 c;\nvoid main() {}\n"),
              "t.frag:2: input uint id meets output int id");
}

}  // namespace
}  // namespace st::skeleton
