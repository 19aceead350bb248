// gl_api.h: the GL entry points the reference uses, as a table of function
// pointers that the context fills in.
//
// We never call GL through linked symbols. OSMesa exports its own gl*
// functions and glvnd's libGL/libOpenGL export dispatch stubs of the same
// names; whichever the dynamic linker meets first takes every call (see
// ../shared/notes/llvmpipe.md), so with two GL platforms in one tool a linked
// glCreateShader may land in the wrong one. Each context instead asks its own
// platform for each function (OSMesaGetProcAddress, eglGetProcAddress) and
// the renderer calls through the table: gl.CreateShader(...).
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>

namespace st {

// Every GL function the reference calls, without its "gl" prefix. Add a
// function here before using it; load_gl_api refuses a platform that lacks
// one.
#define ST_GL_FUNCTIONS(X)                                                                                  \
    X(ActiveTexture) X(AttachShader) X(BindBuffer) X(BindFragDataLocation) X(BindFramebuffer) X(BindRenderbuffer) X(BindSampler)     \
    X(BindTexture) X(BindVertexArray) X(BlendEquation) X(BlendFunc) X(BlendFuncSeparate) X(BufferData)      \
    X(BufferSubData) X(CheckFramebufferStatus) X(Clear) X(ClearColor) X(ClearDepth) X(CompileShader)        \
    X(CreateProgram) X(CreateShader) X(DeleteBuffers) X(DeleteFramebuffers) X(DeleteProgram)                \
    X(DeleteRenderbuffers) X(DeleteSamplers) X(DeleteShader) X(DeleteTextures) X(DeleteVertexArrays)        \
    X(DepthFunc) X(DepthMask) X(Disable) X(DrawBuffers) X(DrawArrays) X(DrawElements) X(Enable) X(EnableVertexAttribArray) \
    X(Finish) X(FramebufferRenderbuffer) X(FramebufferTexture2D) X(GenBuffers) X(GenFramebuffers)          \
    X(GenRenderbuffers) X(GenSamplers) X(GenTextures) X(GenVertexArrays) X(GetError) X(GetProgramInfoLog)  \
    X(GetAttribLocation) X(GetProgramiv) X(GetShaderInfoLog) X(GetShaderiv) X(GetString) X(GetUniformLocation) X(LinkProgram)    \
    X(PixelStorei) X(ReadPixels) X(RenderbufferStorage) X(SamplerParameterf) X(SamplerParameteri)         \
    X(ShaderSource) X(TexParameterf) X(TexParameteri) X(TexStorage2D) X(TexSubImage2D) X(Uniform1f)         \
    X(Uniform1i) X(Uniform2f) X(Uniform3f) X(Uniform4f) X(UniformMatrix4fv) X(UseProgram)                   \
    X(Uniform2i) X(Uniform3i) X(Uniform4i) X(Uniform1ui) X(Uniform2ui) X(Uniform3ui) X(Uniform4ui)          \
    X(UniformMatrix2fv) X(UniformMatrix3fv) X(UniformMatrix2x3fv) X(UniformMatrix2x4fv) X(UniformMatrix3x2fv)  \
    X(UniformMatrix3x4fv) X(UniformMatrix4x2fv) X(UniformMatrix4x3fv)                                        \
    X(Uniform1d) X(Uniform2d) X(Uniform3d) X(Uniform4d) X(UniformMatrix2dv) X(UniformMatrix3dv)              \
    X(UniformMatrix4dv) X(UniformMatrix2x3dv) X(UniformMatrix2x4dv) X(UniformMatrix3x2dv)                  \
    X(UniformMatrix3x4dv) X(UniformMatrix4x2dv) X(UniformMatrix4x3dv)                                        \
    X(GetActiveUniformBlockiv) X(GetActiveUniformsiv) X(GetActiveUniformName) X(UniformBlockBinding)         \
    X(BindBufferBase)                                                                                       \
    X(VertexAttribPointer) X(Viewport)

// The prototypes above are only read for their types (decltype); nothing
// links against them.
struct GlApi {
#define ST_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
    ST_GL_FUNCTIONS(ST_GL_MEMBER)
#undef ST_GL_MEMBER
};

// A platform's lookup: the entry point named, or null.
using GlProcLookup = std::function<void (*(const char* name))()>;

// Fills every entry through `lookup`. Throws std::runtime_error naming the
// platform and the first function it lacks.
GlApi load_gl_api(const char* platform, const GlProcLookup& lookup);

}  // namespace st
