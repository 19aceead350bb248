// gl_renderer.cpp: Frame -> GL objects -> draws -> float read-back.
//
// Mirrors raster/cpu_renderer.cpp step for step: same targets (RGBA32F and
// 32-bit float depth), same clear, same draw order, same blend and depth
// state. Anything set here that changes pixels must be set there too.
#include "gl/gl_renderer.h"

#include "gl/gl_context.h"
#include "gl/shader_files.h"
#include "gl/uniform_blocks.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace st {

namespace {

// Reads a shader and splices in `#include "file"` lines (paths relative to
// the including file), so programs can share model code the way their twins
// share C++ functions. The #line directives keep GL log line numbers
// meaningful: the second number is the source-string index, and the log's
// file is named in our error message.
std::string read_source(const std::string& path, int depth = 0) {
    if (depth > 8) throw std::runtime_error(path + ": #include nested too deeply");
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read shader " + path);
    const std::string dir = path.substr(0, path.find_last_of('/') + 1);
    std::string out, line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const auto first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
            const auto open = line.find('"'), close = line.rfind('"');
            if (open == std::string::npos || close <= open)
                throw std::runtime_error(path + ":" + std::to_string(number) + ": malformed #include");
            out += read_source(dir + line.substr(open + 1, close - open - 1), depth + 1);
            out += "#line " + std::to_string(number + 1) + "\n";
            continue;
        }
        out += line + "\n";
    }
    return out;
}

GLuint compile(const GlApi& gl, GLenum type, const std::string& path, const std::string& source) {
    GLuint shader = gl.CreateShader(type);
    const char* text = source.c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
        gl.DeleteShader(shader);
        throw std::runtime_error(path + ": GLSL compile failed\n" + log);
    }
    return shader;
}

GLuint link(const GlApi& gl, const std::string& vert_path, const std::string& frag_path, const std::string& frag_source,
            const std::vector<std::string>& output_names) {
    GLuint vs = compile(gl, GL_VERTEX_SHADER, vert_path, read_source(vert_path));
    GLuint fs = 0;
    try {
        fs = compile(gl, GL_FRAGMENT_SHADER, frag_path, frag_source);
    } catch (...) {
        gl.DeleteShader(vs);
        throw;
    }
    GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    for (size_t k = 0; k < output_names.size(); ++k) gl.BindFragDataLocation(program, GLuint(k), output_names[k].c_str());
    gl.LinkProgram(program);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
        gl.DeleteProgram(program);
        throw std::runtime_error(vert_path + " + " + frag_path + ": GLSL link failed\n" + log);
    }
    return program;
}

GLint gl_wrap(TextureWrap w) {
    switch (w) {
        case TextureWrap::Repeat: return GL_REPEAT;
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}
GLenum gl_factor(BlendFactor f) {
    switch (f) {
        case BlendFactor::Zero: return GL_ZERO;
        case BlendFactor::One: return GL_ONE;
        case BlendFactor::SrcColor: return GL_SRC_COLOR;
        case BlendFactor::OneMinusSrcColor: return GL_ONE_MINUS_SRC_COLOR;
        case BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
        case BlendFactor::OneMinusSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstColor: return GL_DST_COLOR;
        case BlendFactor::OneMinusDstColor: return GL_ONE_MINUS_DST_COLOR;
        case BlendFactor::DstAlpha: return GL_DST_ALPHA;
        case BlendFactor::OneMinusDstAlpha: return GL_ONE_MINUS_DST_ALPHA;
    }
    return GL_ONE;
}
GLint gl_mag_filter(TextureFilter f) { return f == TextureFilter::Linear ? GL_LINEAR : GL_NEAREST; }
GLint gl_min_filter(TextureFilter f, MipFilter mip) {
    const bool linear = f == TextureFilter::Linear;
    switch (mip) {
        case MipFilter::None: return linear ? GL_LINEAR : GL_NEAREST;
        case MipFilter::Nearest: return linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
        case MipFilter::Linear: return linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
    }
    return GL_NEAREST;
}
GLenum gl_internal_format(TextureFormat f) {
    switch (f) {
        case TextureFormat::RGBA8: return GL_RGBA8;
        case TextureFormat::R32F: return GL_R32F;
        case TextureFormat::RGBA16F: return GL_RGBA16F;
        case TextureFormat::RGBA32F: return GL_RGBA32F;
        case TextureFormat::SRGB8_ALPHA8: return GL_SRGB8_ALPHA8;
    }
    return GL_RGBA32F;
}

// Level by level, from the host's texels: RGBA8 as bytes, the float formats
// as RGBA floats that GL converts to the storage format (texel_formats.h).
// An FBO drawing into `level` of the 2D texture `colour` (width x height
// at that level), with its own 32-bit float depth buffer; left bound.
void make_framebuffer(const GlApi& gl, GLuint colour, int level, int width, int height, GLuint& fbo, GLuint& depth) {
    gl.GenRenderbuffers(1, &depth);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, level);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("GL: incomplete framebuffer " + std::to_string(width) + "x" +
                                 std::to_string(height) + " at level " + std::to_string(level));
}

GLenum gl_target(const Texture& tex) { return tex.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D; }

// The sampling state of `tex` (filters, wraps, LOD bias and range), set
// through `seti` / `setf`: on the texture itself for an uploaded one, on a
// sampler object for a render target, so both carry the same seven values.
template <class SetI, class SetF>
void set_sampling(const Texture& tex, SetI seti, SetF setf) {
    seti(GL_TEXTURE_MIN_FILTER, gl_min_filter(tex.min_filter, tex.mip_filter));
    seti(GL_TEXTURE_MAG_FILTER, gl_mag_filter(tex.mag_filter));
    seti(GL_TEXTURE_WRAP_S, gl_wrap(tex.wrap_s));
    seti(GL_TEXTURE_WRAP_T, gl_wrap(tex.wrap_t));
    setf(GL_TEXTURE_LOD_BIAS, tex.lod_bias);
    setf(GL_TEXTURE_MIN_LOD, tex.min_lod);
    setf(GL_TEXTURE_MAX_LOD, tex.max_lod);
}

// Level by level and face by face, from the host's texels: RGBA8 as bytes,
// the float formats as RGBA floats that GL converts to the storage format
// (texture/texel_formats.h), into the texture bound to gl_target(tex).
void upload_texture(const GlApi& gl, const Texture& tex) {
    const GLenum target = gl_target(tex);
    gl.TexStorage2D(target, tex.level_count(), gl_internal_format(tex.format), tex.width, tex.height);
    for (int level = 0; level < tex.level_count(); ++level) {
        const TextureLevel* l = level ? &tex.mips[size_t(level - 1)] : nullptr;
        const int w = l ? l->width : tex.width, h = l ? l->height : tex.height;
        const size_t face_values = size_t(w) * size_t(h) * 4;
        for (int face = 0; face < tex.faces(); ++face) {
            const GLenum image = tex.cube ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) : GL_TEXTURE_2D;
            const size_t at = size_t(face) * face_values;
            if (holds_bytes(tex.format))
                gl.TexSubImage2D(image, level, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE,
                                (l ? l->texels8.data() : tex.texels8.data()) + at);
            else
                gl.TexSubImage2D(image, level, 0, 0, w, h, GL_RGBA, GL_FLOAT,
                                (l ? l->texels32.data() : tex.texels32.data()) + at);
        }
    }
    set_sampling(tex, [&](GLenum pname, GLint v) { gl.TexParameteri(target, pname, v); },
                 [&](GLenum pname, GLfloat v) { gl.TexParameterf(target, pname, v); });
}

void set_uniform(const GlApi& gl, GLuint program, const Uniform& u) {
    const GLint loc = gl.GetUniformLocation(program, u.name.c_str());
    if (loc < 0) return;  // not used by this program (or optimised away)
    const double* d = u.value.data();
    // The values as glUniform*f, *i and *ui take them (each exact: a float
    // uniform holds a float's value, an integer one an integer's).
    std::array<float, 16> v{};
    std::array<GLint, 4> i{};
    std::array<GLuint, 4> ui{};
    for (size_t k = 0; k < v.size(); ++k) v[k] = float(d[k]);
    for (size_t k = 0; k < i.size(); ++k) {
        ui[k] = uniform_type_is_integer(u.type) ? GLuint(uniform_integer_bits(d[k])) : 0u;
        i[k] = GLint(int32_t(ui[k]));
    }
    switch (u.type) {
        case UniformType::Float: gl.Uniform1f(loc, v[0]); break;
        case UniformType::Vec2: gl.Uniform2f(loc, v[0], v[1]); break;
        case UniformType::Vec3: gl.Uniform3f(loc, v[0], v[1], v[2]); break;
        case UniformType::Vec4: gl.Uniform4f(loc, v[0], v[1], v[2], v[3]); break;
        case UniformType::Int: gl.Uniform1i(loc, i[0]); break;
        case UniformType::Mat4: gl.UniformMatrix4fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::IVec2: gl.Uniform2i(loc, i[0], i[1]); break;
        case UniformType::IVec3: gl.Uniform3i(loc, i[0], i[1], i[2]); break;
        case UniformType::IVec4: gl.Uniform4i(loc, i[0], i[1], i[2], i[3]); break;
        case UniformType::UInt: gl.Uniform1ui(loc, ui[0]); break;
        case UniformType::UVec2: gl.Uniform2ui(loc, ui[0], ui[1]); break;
        case UniformType::UVec3: gl.Uniform3ui(loc, ui[0], ui[1], ui[2]); break;
        case UniformType::UVec4: gl.Uniform4ui(loc, ui[0], ui[1], ui[2], ui[3]); break;
        case UniformType::Mat2: gl.UniformMatrix2fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat3: gl.UniformMatrix3fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat2x3: gl.UniformMatrix2x3fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat2x4: gl.UniformMatrix2x4fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat3x2: gl.UniformMatrix3x2fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat3x4: gl.UniformMatrix3x4fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat4x2: gl.UniformMatrix4x2fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Mat4x3: gl.UniformMatrix4x3fv(loc, 1, GL_FALSE, v.data()); break;
        case UniformType::Double: gl.Uniform1d(loc, d[0]); break;
        case UniformType::DVec2: gl.Uniform2d(loc, d[0], d[1]); break;
        case UniformType::DVec3: gl.Uniform3d(loc, d[0], d[1], d[2]); break;
        case UniformType::DVec4: gl.Uniform4d(loc, d[0], d[1], d[2], d[3]); break;
        case UniformType::DMat2: gl.UniformMatrix2dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat3: gl.UniformMatrix3dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat4: gl.UniformMatrix4dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat2x3: gl.UniformMatrix2x3dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat2x4: gl.UniformMatrix2x4dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat3x2: gl.UniformMatrix3x2dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat3x4: gl.UniformMatrix3x4dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat4x2: gl.UniformMatrix4x2dv(loc, 1, GL_FALSE, d); break;
        case UniformType::DMat4x3: gl.UniformMatrix4x3dv(loc, 1, GL_FALSE, d); break;
    }
}

}  // namespace

std::string read_glsl_source(const std::string& path) { return read_source(path); }

struct GlRenderer::State {
    struct Draw {
        GLuint program = 0, vao = 0, vbo = 0, ebo = 0;
        GLsizei index_count = 0;
        std::vector<GLuint> textures;         // per unit; a render target's texture is not the draw's
        std::vector<GLenum> texture_targets;  // GL_TEXTURE_2D or GL_TEXTURE_CUBE_MAP, per unit
        std::vector<GLuint> samplers;         // per unit: 0, or a sampler object for a render target
        std::vector<GLuint> owned_textures;
        DrawState state;
        std::shared_ptr<const HostStage> host_stage;
        VertexArray vertices;  // kept only when a host stage rewrites them per frame
        // Set on every execute, after glUseProgram: draws share a program
        // per (vertex, fragment) pair, and uniform values are the program's,
        // so values set once at prepare would be the last draw's for all.
        std::vector<Uniform> uniforms;
        std::vector<std::string> sampler_names;  // per unit
        // Per active uniform block: its buffer, bound to binding point =
        // the block's index at each execute (gl/uniform_blocks.h).
        std::vector<GLuint> block_buffers;
        std::vector<GLuint> block_indices;
    };
    // A pass: its own RGBA32F target (the frame's image), or a level of a
    // named target (fbo and colour then belong to `named`).
    struct Target {
        GLuint fbo = 0, colour = 0, depth = 0;
        bool owned = true;
        // A pass with several outputs draws through an FBO of its own.
        GLuint outputs_fbo = 0, outputs_depth = 0;
        int width = 0, height = 0;
        int viewport[4] = {0, 0, 0, 0};
        bool clear = true;
        glm::vec4 clear_colour;
        float clear_depth = 1.0f;
        std::vector<Draw> draws;
    };
    // A named render target: one texture, and per level an FBO with its
    // own depth buffer.
    struct Named {
        RenderTarget desc;
        GLuint texture = 0;
        std::vector<GLuint> fbos, depths;
    };
    // Per (vertex, fragment, output names), kept across frames.
    std::map<std::tuple<std::string, std::string, std::vector<std::string>>, GLuint> programs;
    // Per program, the uniforms the last draw that used it set. A program
    // keeps its uniform values across draws and frames, so one a later draw
    // leaves out would read the earlier draw's value (an earlier scene's, in
    // one process); each execute sets those back to 0, what a program that
    // was never given them reads (explore conformance --seed 31).
    std::map<GLuint, std::vector<Uniform>> last_uniforms;
    std::vector<Target> passes;
    std::map<std::string, Named> named;

    void release_passes(const GlApi& gl) {
        for (Target& t : passes) {
            for (Draw& d : t.draws) {
                gl.DeleteVertexArrays(1, &d.vao);
                gl.DeleteBuffers(1, &d.vbo);
                gl.DeleteBuffers(1, &d.ebo);
                if (!d.block_buffers.empty()) gl.DeleteBuffers(GLsizei(d.block_buffers.size()), d.block_buffers.data());
                gl.DeleteTextures(GLsizei(d.owned_textures.size()), d.owned_textures.data());
                for (GLuint sampler : d.samplers)
                    if (sampler) gl.DeleteSamplers(1, &sampler);
            }
            if (t.outputs_fbo) {
                gl.DeleteFramebuffers(1, &t.outputs_fbo);
                gl.DeleteRenderbuffers(1, &t.outputs_depth);
            }
            if (t.owned) {
                gl.DeleteFramebuffers(1, &t.fbo);
                gl.DeleteTextures(1, &t.colour);
                gl.DeleteRenderbuffers(1, &t.depth);
            }
        }
        passes.clear();
        for (auto& [name, n] : named) {
            gl.DeleteFramebuffers(GLsizei(n.fbos.size()), n.fbos.data());
            gl.DeleteRenderbuffers(GLsizei(n.depths.size()), n.depths.data());
            gl.DeleteTextures(1, &n.texture);
        }
        named.clear();
    }
};

GlRenderer::GlRenderer(const std::vector<std::string>& glsl_roots, GlPlatform platform)
    : shaders_(std::make_unique<ShaderFiles>(glsl_roots)), context_(make_gl_context(platform)), state_(new State) {}

GlRenderer::~GlRenderer() {
    context_->make_current();
    const GlApi& gl = context_->gl();
    state_->release_passes(gl);
    for (auto& [key, program] : state_->programs) gl.DeleteProgram(program);
}

void GlRenderer::set_fragment_filter(FragmentFilter filter) {
    context_->make_current();
    const GlApi& gl = context_->gl();
    for (auto& [key, program] : state_->programs) gl.DeleteProgram(program);
    state_->programs.clear();
    state_->last_uniforms.clear();
    fragment_filter_ = std::move(filter);
}

std::string GlRenderer::renderer() const { return context_->renderer(); }
std::string GlRenderer::version() const { return context_->version(); }
GlPlatform GlRenderer::platform() const { return context_->platform(); }

unsigned GlRenderer::program(const std::string& vertex, const std::string& fragment,
                             const std::vector<std::string>& output_names) {
    auto key = std::make_tuple(vertex, fragment, output_names);
    auto it = state_->programs.find(key);
    if (it == state_->programs.end()) {
        const std::string& frag_path = shaders_->path(fragment, ".frag");
        std::string frag_source = read_source(frag_path);
        if (fragment_filter_) frag_source = fragment_filter_(fragment, frag_source);
        it = state_->programs
                 .emplace(key, link(context_->gl(), shaders_->path(vertex, ".vert"), frag_path, frag_source, output_names))
                 .first;
    }
    return it->second;
}

std::vector<GlRenderer::ActiveUniform> GlRenderer::active_uniforms(const std::string& vertex,
                                                                   const std::string& fragment,
                                                                   const std::vector<std::string>& output_names) {
    context_->make_current();
    const GlApi& gl = context_->gl();
    const GLuint p = program(vertex, fragment, output_names);
    GLint count = 0;
    gl.GetProgramiv(p, GL_ACTIVE_UNIFORMS, &count);
    std::vector<ActiveUniform> out;
    for (GLint i = 0; i < count; ++i) {
        const GLuint index = GLuint(i);
        GLint size = 1, name_length = 0;
        gl.GetActiveUniformsiv(p, 1, &index, GL_UNIFORM_SIZE, &size);
        gl.GetActiveUniformsiv(p, 1, &index, GL_UNIFORM_NAME_LENGTH, &name_length);
        std::string name(size_t(std::max(name_length, 1)), '\0');
        GLsizei written = 0;
        gl.GetActiveUniformName(p, index, GLsizei(name.size()), &written, name.data());
        name.resize(size_t(std::max(written, 0)));
        out.push_back({name, std::max(size, 1)});
    }
    return out;
}

void GlRenderer::prepare(const Frame& frame) {
    context_->make_current();
    const GlApi& gl = context_->gl();
    state_->release_passes(gl);
    // Cube maps filter across their faces, as real renderers set them.
    gl.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    for (const RenderTarget& rt : frame.targets) {
        State::Named n;
        n.desc = rt;
        gl.GenTextures(1, &n.texture);
        gl.BindTexture(GL_TEXTURE_2D, n.texture);
        gl.TexStorage2D(GL_TEXTURE_2D, rt.levels, rt.format == TargetFormat::RGBA16F ? GL_RGBA16F : GL_RGBA32F,
                       rt.width, rt.height);
        for (int level = 0; level < rt.levels; ++level) {
            GLuint fbo = 0, depth = 0;
            make_framebuffer(gl, n.texture, level, std::max(1, rt.width >> level), std::max(1, rt.height >> level),
                             fbo, depth);
            // Start from zero, as the CPU side does.
            gl.ClearColor(0, 0, 0, 0);
            gl.Clear(GL_COLOR_BUFFER_BIT);
            n.fbos.push_back(fbo);
            n.depths.push_back(depth);
        }
        state_->named[rt.name] = std::move(n);
    }
    // The frame's passes (no target) share one texture per size, as the CPU
    // side keeps one frame image: a pass that does not clear draws over the
    // earlier passes' image, and the first starts from zero.
    std::map<std::pair<int, int>, size_t> frame_owner;  // size -> index of the pass owning its texture
    for (const Pass& pass : frame.passes) {
        State::Target t;
        t.width = pass.width;
        t.height = pass.height;
        t.clear = pass.clear;
        t.clear_colour = pass.clear_colour;
        t.clear_depth = pass.clear_depth;
        t.viewport[0] = pass.viewport_x;
        t.viewport[1] = pass.viewport_y;
        t.viewport[2] = pass.viewport_width ? pass.viewport_width : pass.width;
        t.viewport[3] = pass.viewport_height ? pass.viewport_height : pass.height;
        if (!pass.target.empty()) {
            const State::Named& n = state_->named.at(pass.target);
            t.owned = false;
            t.fbo = n.fbos[size_t(pass.level)];
            t.colour = n.texture;
        } else if (const auto owner = frame_owner.find({t.width, t.height}); owner != frame_owner.end()) {
            const State::Target& first = state_->passes[owner->second];
            t.owned = false;
            t.fbo = first.fbo;
            t.colour = first.colour;
        } else {
            gl.GenTextures(1, &t.colour);
            gl.BindTexture(GL_TEXTURE_2D, t.colour);
            gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, t.width, t.height);
            make_framebuffer(gl, t.colour, 0, t.width, t.height, t.fbo, t.depth);
            // Start from zero, as the CPU side does: a first pass that does
            // not clear (clear: false) would otherwise keep whatever memory
            // llvmpipe handed out, often the last frame's (found by explore:
            // conformance-branch-texture with clear=false).
            gl.ClearColor(0, 0, 0, 0);
            gl.Clear(GL_COLOR_BUFFER_BIT);
            frame_owner[{t.width, t.height}] = state_->passes.size();
        }

        if (!pass.outputs.empty()) {
            // Several render targets: the pass's colour buffer at attachment
            // 0 and each output's level at 1, 2, ..., as glDrawBuffers maps
            // fragment outputs 0, 1, 2, ... to them, with a depth buffer.
            gl.GenRenderbuffers(1, &t.outputs_depth);
            gl.BindRenderbuffer(GL_RENDERBUFFER, t.outputs_depth);
            gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, t.width, t.height);
            gl.GenFramebuffers(1, &t.outputs_fbo);
            gl.BindFramebuffer(GL_FRAMEBUFFER, t.outputs_fbo);
            gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.colour,
                                    pass.target.empty() ? 0 : pass.level);
            std::vector<GLenum> buffers = {GL_COLOR_ATTACHMENT0};
            for (const PassOutput& o : pass.outputs) {
                const auto n = state_->named.find(o.target);
                if (n == state_->named.end()) throw std::runtime_error("GL: a pass output names unknown target " + o.target);
                const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + buffers.size());
                gl.FramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, n->second.texture, o.level);
                buffers.push_back(attachment);
            }
            gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.outputs_depth);
            gl.DrawBuffers(GLsizei(buffers.size()), buffers.data());
            if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
                throw std::runtime_error("GL: incomplete framebuffer for a pass with " + std::to_string(buffers.size()) +
                                         " outputs");
        }
        for (const DrawCall& dc : pass.draws) {
            State::Draw d;
            d.program = program(dc.vertex, dc.fragment, dc.output_names);
            d.state = dc.state;
            if (dc.host_stage) {
                d.host_stage = dc.host_stage;
                d.vertices = dc.vertices;
            }
            d.index_count = GLsizei(dc.indices.size());
            gl.GenVertexArrays(1, &d.vao);
            gl.BindVertexArray(d.vao);
            gl.GenBuffers(1, &d.vbo);
            gl.BindBuffer(GL_ARRAY_BUFFER, d.vbo);
            gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(dc.vertices.data.size() * sizeof(glm::vec4)),
                         dc.vertices.data.data(), GL_STATIC_DRAW);
            const GLsizei stride = GLsizei(dc.vertices.attribute_count * sizeof(glm::vec4));
            for (int a = 0; a < dc.vertices.attribute_count; ++a) {
                // Column a feeds location a, or the location GL gave the
                // input it names (none: the compiler removed it).
                const std::vector<std::string>& names = dc.vertices.names;
                const GLint location = names.empty()            ? GLint(a)
                                       : size_t(a) < names.size() ? gl.GetAttribLocation(d.program, names[size_t(a)].c_str())
                                                                  : -1;
                if (location < 0) continue;
                gl.EnableVertexAttribArray(GLuint(location));
                gl.VertexAttribPointer(GLuint(location), 4, GL_FLOAT, GL_FALSE, stride,
                                      reinterpret_cast<const void*>(size_t(a) * sizeof(glm::vec4)));
            }
            gl.GenBuffers(1, &d.ebo);
            gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.ebo);
            gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(dc.indices.size() * sizeof(uint32_t)),
                         dc.indices.data(), GL_STATIC_DRAW);
            gl.BindVertexArray(0);

            d.uniforms = dc.uniforms;
            for (const UniformBlockData& block : uniform_block_data(gl, d.program, dc.uniforms)) {
                GLuint buffer = 0;
                gl.GenBuffers(1, &buffer);
                gl.BindBuffer(GL_UNIFORM_BUFFER, buffer);
                gl.BufferData(GL_UNIFORM_BUFFER, GLsizeiptr(block.bytes.size()), block.bytes.data(), GL_STATIC_DRAW);
                d.block_buffers.push_back(buffer);
                d.block_indices.push_back(block.index);
            }
            for (size_t unit = 0; unit < dc.textures.size(); ++unit) {
                const Texture& tex = dc.textures[unit];
                GLuint name = 0, sampler = 0;
                if (!tex.target.empty()) {
                    // A render target: its texture, filtered by a sampler object.
                    name = state_->named.at(tex.target).texture;
                    gl.GenSamplers(1, &sampler);
                    set_sampling(tex, [&](GLenum pname, GLint v) { gl.SamplerParameteri(sampler, pname, v); },
                                 [&](GLenum pname, GLfloat v) { gl.SamplerParameterf(sampler, pname, v); });
                } else {
                    gl.GenTextures(1, &name);
                    gl.BindTexture(gl_target(tex), name);
                    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
                    upload_texture(gl, tex);
                    d.owned_textures.push_back(name);
                }
                d.sampler_names.push_back(tex.sampler);
                d.textures.push_back(name);
                d.texture_targets.push_back(gl_target(tex));
                d.samplers.push_back(sampler);
            }
            t.draws.push_back(std::move(d));
        }
        state_->passes.push_back(std::move(t));
    }
    if (GLenum err = gl.GetError(); err != GL_NO_ERROR)
        throw std::runtime_error("GL error " + std::to_string(err) + " while preparing the frame");
}

void GlRenderer::execute() {
    context_->make_current();
    const GlApi& gl = context_->gl();
    gl.Disable(GL_DITHER);
    gl.Disable(GL_CULL_FACE);
    for (State::Target& t : state_->passes) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, t.outputs_fbo ? t.outputs_fbo : t.fbo);
        gl.Viewport(t.viewport[0], t.viewport[1], t.viewport[2], t.viewport[3]);
        gl.DepthMask(GL_TRUE);
        gl.ClearColor(t.clear_colour.r, t.clear_colour.g, t.clear_colour.b, t.clear_colour.a);
        gl.ClearDepth(t.clear_depth);
        gl.Clear(t.clear ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT : GL_DEPTH_BUFFER_BIT);
        for (State::Draw& d : t.draws) {
            if (d.state.depth_test) {
                gl.Enable(GL_DEPTH_TEST);
                gl.DepthFunc(GL_LESS);
            } else {
                gl.Disable(GL_DEPTH_TEST);
            }
            gl.DepthMask(d.state.depth_write ? GL_TRUE : GL_FALSE);
            switch (d.state.blend) {
                case BlendMode::None: gl.Disable(GL_BLEND); break;
                case BlendMode::OneSrcAlpha:
                    gl.Enable(GL_BLEND);
                    gl.BlendFunc(GL_ONE, GL_SRC_ALPHA);
                    break;
                case BlendMode::SrcAlphaOneMinusSrcAlpha:
                    gl.Enable(GL_BLEND);
                    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                    break;
                case BlendMode::Factors: {
                    const BlendFactors& f = d.state.factors;
                    gl.Enable(GL_BLEND);
                    gl.BlendEquation(GL_FUNC_ADD);
                    gl.BlendFuncSeparate(gl_factor(f.src_rgb), gl_factor(f.dst_rgb), gl_factor(f.src_alpha),
                                        gl_factor(f.dst_alpha));
                    break;
                }
            }
            if (d.host_stage) {
                // The host's per-frame work and its upload belong to the frame.
                d.host_stage->run(d.vertices);
                gl.BindBuffer(GL_ARRAY_BUFFER, d.vbo);
                gl.BufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(d.vertices.data.size() * sizeof(glm::vec4)),
                                d.vertices.data.data());
            }
            gl.UseProgram(d.program);
            std::vector<Uniform>& last = state_->last_uniforms[d.program];
            for (const Uniform& earlier : last) {
                const bool set_now = std::any_of(d.uniforms.begin(), d.uniforms.end(),
                                                 [&](const Uniform& u) { return u.name == earlier.name; });
                if (!set_now) set_uniform(gl, d.program, Uniform{earlier.name, earlier.type, {}});
            }
            for (const Uniform& u : d.uniforms) set_uniform(gl, d.program, u);
            last = d.uniforms;
            for (size_t b = 0; b < d.block_buffers.size(); ++b) {
                gl.UniformBlockBinding(d.program, d.block_indices[b], d.block_indices[b]);
                gl.BindBufferBase(GL_UNIFORM_BUFFER, d.block_indices[b], d.block_buffers[b]);
            }
            for (size_t unit = 0; unit < d.textures.size(); ++unit) {
                const GLint loc = gl.GetUniformLocation(d.program, d.sampler_names[unit].c_str());
                if (loc >= 0) gl.Uniform1i(loc, GLint(unit));
                gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
                gl.BindTexture(d.texture_targets[unit], d.textures[unit]);
                gl.BindSampler(GLuint(unit), d.samplers[unit]);
            }
            gl.BindVertexArray(d.vao);
            gl.DrawElements(GL_TRIANGLES, d.index_count, GL_UNSIGNED_INT, nullptr);
        }
    }
    gl.Finish();
    if (GLenum err = gl.GetError(); err != GL_NO_ERROR)
        throw std::runtime_error("GL error " + std::to_string(err) + " while drawing");
}

namespace {

Image read_fbo(const GlApi& gl, GLuint fbo, int width, int height) {
    Image bottom_up(width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, bottom_up.rgba.data());
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        std::copy_n(bottom_up.pixel(0, height - 1 - y), size_t(width) * 4, image.pixel(0, y));
    return image;
}

}  // namespace

Image GlRenderer::read_back() {
    context_->make_current();
    const GlApi& gl = context_->gl();
    for (auto t = state_->passes.rbegin(); t != state_->passes.rend(); ++t)
        if (t->owned) return read_fbo(gl, t->fbo, t->width, t->height);
    throw std::runtime_error("GL: nothing rendered");
}

Image GlRenderer::read_back(const std::string& target, int level) {
    context_->make_current();
    const GlApi& gl = context_->gl();
    const auto it = state_->named.find(target);
    if (it == state_->named.end() || level < 0 || level >= it->second.desc.levels)
        throw std::runtime_error("GL: no render target " + target + " level " + std::to_string(level));
    const RenderTarget& rt = it->second.desc;
    return read_fbo(gl, it->second.fbos[size_t(level)], std::max(1, rt.width >> level), std::max(1, rt.height >> level));
}

}  // namespace st
