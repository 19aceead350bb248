// gl_renderer_test.cpp: live checks of the GL reference on llvmpipe: the
// float-to-8-bit conversion we apply to float images is the one llvmpipe
// applies when it writes an RGBA8 target, and a broken shader is reported
// with its GL log.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "gl/gl_context.h"
#include "gl/gl_renderer.h"
#include "image/unorm8.h"

namespace st {

namespace {

GLuint compile_program(const char* vs_src, const char* fs_src) {
    auto compile = [](GLenum type, const char* src) {
        GLuint s = glCreateShader(type);
        glShaderSource(s, 1, &src, nullptr);
        glCompileShader(s);
        GLint ok = 0;
        glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
        EXPECT_TRUE(ok);
        return s;
    };
    GLuint p = glCreateProgram();
    glAttachShader(p, compile(GL_VERTEX_SHADER, vs_src));
    glAttachShader(p, compile(GL_FRAGMENT_SHADER, fs_src));
    glLinkProgram(p);
    return p;
}

// Renders `program` as a full-screen triangle into a w x h target of
// `format` and reads back `type` texels.
template <class T>
std::vector<T> draw_fullscreen(GLuint program, GLenum format, GLenum type, int w, int h) {
    GLuint tex, fbo, vao;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, w, h);
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glUseProgram(program);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    std::vector<T> out(size_t(w) * h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, type, out.data());
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
    glDeleteVertexArrays(1, &vao);
    return out;
}

}  // namespace

// Every pixel writes a different value in [0, 1] (65,536 steps per channel,
// offset per channel so that halfway cases of x * 255 come up): the 8-bit
// target must hold exactly to_unorm8 of what the float target holds.
TEST(GlReference, Unorm8ConversionMatchesAnRgba8Target) {
    auto context = make_osmesa_context();
    const char* vs =
        "#version 450 core\n"
        "void main() {\n"
        "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
        "  gl_Position = vec4(p, 0.0, 1.0);\n"
        "}\n";
    const char* fs =
        "#version 450 core\n"
        "layout(location = 0) out vec4 colour;\n"
        "void main() {\n"
        "  float i = floor(gl_FragCoord.y) * 256.0 + floor(gl_FragCoord.x);\n"
        "  colour = vec4(i / 65535.0, (i + 0.5) / 65536.0, fract(i * 0.00390625) + 0.5 / 255.0,\n"
        "                (floor(i / 255.0) + 0.5) / 255.0);\n"
        "}\n";
    const GLuint program = compile_program(vs, fs);
    const auto floats = draw_fullscreen<float>(program, GL_RGBA32F, GL_FLOAT, 256, 256);
    const auto bytes = draw_fullscreen<unsigned char>(program, GL_RGBA8, GL_UNSIGNED_BYTE, 256, 256);
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
    glDeleteProgram(program);
}

TEST(GlReference, CompileErrorNamesTheFileAndCarriesTheLog) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("shadertwin-glsl-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "broken.vert") << "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    std::ofstream(dir / "broken.frag") << "#version 450 core\nout vec4 c;\nvoid main() { c = undefined_thing; }\n";
    GlRenderer gl({dir.string()});
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

}  // namespace st
