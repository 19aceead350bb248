// gl_renderer.h: the reference backend. Runs a Frame through the real GLSL
// on a GL context (llvmpipe), into RGBA32F framebuffer objects.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "frame/frame.h"
#include "gl/gl_platform.h"
#include "image/image.h"

namespace st {

class GlContext;
class ShaderFiles;

class GlRenderer {
public:
    // `glsl_roots` hold <technique>/<name>.vert|.frag (gl/shader_files.h).
    // Creates the context on `platform` (gl_context.h).
    explicit GlRenderer(const std::vector<std::string>& glsl_roots, GlPlatform platform = GlPlatform::Auto);
    ~GlRenderer();

    // Compiles programs, uploads geometry and textures, creates targets.
    // Throws std::runtime_error (first line says what, then the GL log).
    void prepare(const Frame& frame);
    // Issues every pass's draws and waits for them (glFinish).
    void execute();
    // The frame's image (the last pass without a named target), rows top to
    // bottom.
    Image read_back();
    // One level of a named render target as the frame left it.
    Image read_back(const std::string& target, int level);

    Image render(const Frame& frame) {
        prepare(frame);
        execute();
        return read_back();
    }

    // Rewrites each fragment program's source (its #includes spliced in)
    // before it compiles: `shadertwin probe` builds its probe runs so. An
    // empty filter compiles the files as they are. Drops the programs
    // compiled so far.
    using FragmentFilter = std::function<std::string(const std::string& name, const std::string& source)>;
    void set_fragment_filter(FragmentFilter filter);

    // The uniforms the program of (vertex, fragment) has active, by GL's
    // reflection (compiled if need be): an array once, as "name[0]" with its
    // size; an array of structs member by member ("lights[1].colour"); a
    // block's members as GL names them. What the compiler removed is not
    // among them.
    struct ActiveUniform {
        std::string name;
        int size = 1;
    };
    std::vector<ActiveUniform> active_uniforms(const std::string& vertex, const std::string& fragment,
                                               const std::vector<std::string>& output_names = {});

    std::string renderer() const;
    std::string version() const;
    GlPlatform platform() const;  // the one the context got: OSMesa or EGL

private:
    struct State;
    // Compiled once per pair and DrawCall::output_names.
    unsigned program(const std::string& vertex, const std::string& fragment, const std::vector<std::string>& output_names);
    std::unique_ptr<ShaderFiles> shaders_;
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<State> state_;
    FragmentFilter fragment_filter_;
};

// A GLSL file's text with its `#include "file"` lines spliced in, as the
// renderer compiles it. Throws std::runtime_error naming the file.
std::string read_glsl_source(const std::string& path);

}  // namespace st
