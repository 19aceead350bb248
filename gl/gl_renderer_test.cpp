// gl_renderer_test.cpp: live checks of the GL reference on llvmpipe, on each
// GL platform this machine has: the float-to-8-bit conversion we apply to
// float images is the one llvmpipe applies when it writes an RGBA8 target, a
// broken shader is reported with its GL log, and OSMesa and EGL give the
// same llvmpipe and the same pixels.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "gl/gl_context.h"
#include "gl/gl_renderer.h"
#include "image/unorm8.h"

namespace st {

namespace {

GLuint compile_program(const GlApi& gl, const char* vs_src, const char* fs_src) {
    auto compile = [&gl](GLenum type, const char* src) {
        GLuint s = gl.CreateShader(type);
        gl.ShaderSource(s, 1, &src, nullptr);
        gl.CompileShader(s);
        GLint ok = 0;
        gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
        EXPECT_TRUE(ok);
        return s;
    };
    GLuint p = gl.CreateProgram();
    gl.AttachShader(p, compile(GL_VERTEX_SHADER, vs_src));
    gl.AttachShader(p, compile(GL_FRAGMENT_SHADER, fs_src));
    gl.LinkProgram(p);
    return p;
}

// Renders `program` as a full-screen triangle into a w x h target of
// `format` and reads back `type` texels.
template <class T>
std::vector<T> draw_fullscreen(const GlApi& gl, GLuint program, GLenum format, GLenum type, int w, int h) {
    GLuint tex, fbo, vao;
    gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    EXPECT_EQ(gl.CheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    gl.Viewport(0, 0, w, h);
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
    gl.UseProgram(program);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.Finish();
    std::vector<T> out(size_t(w) * h * 4);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, w, h, GL_RGBA, type, out.data());
    gl.DeleteFramebuffers(1, &fbo);
    gl.DeleteTextures(1, &tex);
    gl.DeleteVertexArrays(1, &vao);
    return out;
}

// Every pixel a different value in [0, 1] (65,536 steps per channel, offset
// per channel so that halfway cases of x * 255 come up), with a
// transcendental so that the platforms' shader compilers are compared too.
const char* kFullscreenVs =
    "#version 450 core\n"
    "void main() {\n"
    "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";
const char* kRampFs =
    "#version 450 core\n"
    "layout(location = 0) out vec4 colour;\n"
    "void main() {\n"
    "  float i = floor(gl_FragCoord.y) * 256.0 + floor(gl_FragCoord.x);\n"
    "  colour = vec4(i / 65535.0, (i + 0.5) / 65536.0, fract(i * 0.00390625) + 0.5 / 255.0,\n"
    "                (floor(i / 255.0) + 0.5) / 255.0);\n"
    "}\n";
const char* kExpFs =
    "#version 450 core\n"
    "layout(location = 0) out vec4 colour;\n"
    "void main() {\n"
    "  float i = floor(gl_FragCoord.y) * 256.0 + floor(gl_FragCoord.x);\n"
    "  colour = vec4(exp(-i / 4096.0), pow(i / 65535.0, 2.2), sqrt(i / 65535.0), inversesqrt(i + 1.0));\n"
    "}\n";

// A platform's context, or a skip when this machine lacks that platform.
std::unique_ptr<GlContext> context_or_skip(GlPlatform platform, std::string& why) {
    try {
        return make_gl_context(platform);
    } catch (const std::exception& e) {
        why = e.what();
        return nullptr;
    }
}

class GlPlatformTest : public ::testing::TestWithParam<GlPlatform> {};

}  // namespace

// The 8-bit target must hold exactly to_unorm8 of what the float target
// holds.
TEST_P(GlPlatformTest, Unorm8ConversionMatchesAnRgba8Target) {
    std::string why;
    auto context = context_or_skip(GetParam(), why);
    if (!context) GTEST_SKIP() << why;
    const GlApi& gl = context->gl();
    const GLuint program = compile_program(gl, kFullscreenVs, kRampFs);
    const auto floats = draw_fullscreen<float>(gl, program, GL_RGBA32F, GL_FLOAT, 256, 256);
    const auto bytes = draw_fullscreen<unsigned char>(gl, program, GL_RGBA8, GL_UNSIGNED_BYTE, 256, 256);
    ASSERT_EQ(floats.size(), bytes.size());
    size_t mismatches = 0, naive_mismatches = 0;
    for (size_t i = 0; i < floats.size(); ++i) {
        mismatches += to_unorm8(floats[i]) != bytes[i];
        const float clamped = std::min(std::max(floats[i], 0.0f), 1.0f);
        naive_mismatches += int(clamped * 255.0f + 0.5f) != int(bytes[i]);
    }
    EXPECT_EQ(mismatches, 0u);
    // The test can tell the conversions apart: the naive rounding misses some.
    EXPECT_GT(naive_mismatches, 0u);
    gl.DeleteProgram(program);
}

TEST_P(GlPlatformTest, ContextIsLlvmpipeGl45Core) {
    std::string why;
    auto context = context_or_skip(GetParam(), why);
    if (!context) GTEST_SKIP() << why;
    EXPECT_EQ(context->platform(), GetParam());
    EXPECT_EQ(context->renderer().rfind("llvmpipe", 0), 0u) << context->renderer();
    EXPECT_EQ(context->version().rfind("4.5 (Core Profile)", 0), 0u) << context->version();
}

TEST_P(GlPlatformTest, CompileErrorNamesTheFileAndCarriesTheLog) {
    std::string why;
    if (!context_or_skip(GetParam(), why)) GTEST_SKIP() << why;
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("shadertwin-glsl-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "broken.vert") << "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    std::ofstream(dir / "broken.frag") << "#version 450 core\nout vec4 c;\nvoid main() { c = undefined_thing; }\n";
    GlRenderer gl({dir.string()}, GetParam());
    EXPECT_EQ(gl.platform(), GetParam());
    Frame frame;
    Pass pass;
    pass.width = pass.height = 4;
    DrawCall draw;
    draw.vertex = draw.fragment = "broken";
    draw.vertices.attribute_count = 1;
    draw.vertices.data.assign(3, glm::vec4(0.0f));
    draw.indices = {0, 1, 2};
    pass.draws.push_back(draw);
    frame.passes.push_back(pass);
    try {
        gl.prepare(frame);
        FAIL() << "a broken shader compiled";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        const std::string first_line = message.substr(0, message.find('\n'));
        EXPECT_NE(first_line.find("broken.frag"), std::string::npos) << message;
        EXPECT_NE(first_line.find("compile failed"), std::string::npos) << message;
        EXPECT_NE(message.find("undefined_thing"), std::string::npos) << message;  // the GL log
    }
    fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Platforms, GlPlatformTest, ::testing::Values(GlPlatform::OSMesa, GlPlatform::Egl),
                         [](const auto& info) { return std::string(gl_platform_name(info.param)); });

// Both platforms in one process, each through its own entry points: the same
// renderer string and the same float pixels, bit for bit.
TEST(GlPlatforms, OsmesaAndEglGiveTheSamePixels) {
    std::string why_osmesa, why_egl;
    auto osmesa = context_or_skip(GlPlatform::OSMesa, why_osmesa);
    auto egl = context_or_skip(GlPlatform::Egl, why_egl);
    if (!osmesa || !egl) GTEST_SKIP() << "needs both platforms: " << why_osmesa << why_egl;
    EXPECT_EQ(osmesa->renderer(), egl->renderer());
    std::vector<float> images[2];
    GlContext* contexts[2] = {osmesa.get(), egl.get()};
    for (int i = 0; i < 2; ++i) {
        contexts[i]->make_current();
        const GlApi& gl = contexts[i]->gl();
        const GLuint program = compile_program(gl, kFullscreenVs, kExpFs);
        images[i] = draw_fullscreen<float>(gl, program, GL_RGBA32F, GL_FLOAT, 256, 256);
        gl.DeleteProgram(program);
    }
    ASSERT_EQ(images[0].size(), images[1].size());
    EXPECT_EQ(std::memcmp(images[0].data(), images[1].data(), images[0].size() * sizeof(float)), 0);
}

// Auto goes on to the next platform when one cannot be had, and says why
// when none can.
TEST(GlPlatforms, AutoTakesTheFirstPlatformThatLoads) {
    const GlContextFactory missing = [] () -> std::unique_ptr<GlContext> {
        throw std::runtime_error("OSMesa: cannot load libOSMesa.so.8 (test)");
    };
    const GlContextFactory also_missing = [] () -> std::unique_ptr<GlContext> {
        throw std::runtime_error("EGL: cannot load libEGL.so.1 (test)");
    };
    std::string why;
    if (!context_or_skip(GlPlatform::Egl, why)) GTEST_SKIP() << why;
    const auto context = first_gl_context({missing, make_egl_context});
    EXPECT_EQ(context->platform(), GlPlatform::Egl);
    try {
        first_gl_context({missing, also_missing});
        FAIL() << "no platform, yet a context";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(),
                     "no GL platform: OSMesa: cannot load libOSMesa.so.8 (test); EGL: cannot load libEGL.so.1 (test)");
    }
}

TEST(GlPlatforms, NamesParseAndBadOnesAreRefused) {
    EXPECT_EQ(parse_gl_platform("auto"), GlPlatform::Auto);
    EXPECT_EQ(parse_gl_platform("osmesa"), GlPlatform::OSMesa);
    EXPECT_EQ(parse_gl_platform("egl"), GlPlatform::Egl);
    EXPECT_THROW(parse_gl_platform("glx"), std::invalid_argument);
    EXPECT_THROW(parse_gl_platform("EGL"), std::invalid_argument);
}

}  // namespace st
