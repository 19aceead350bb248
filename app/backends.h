// backends.h: the two ways to render a Frame, behind one call.
// "cpu" is our rasterizer with the C++ twins; "gl" is the real GLSL on
// llvmpipe. Each backend is created on first use and then kept.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frame/frame.h"
#include "gl/gl_platform.h"
#include "image/image.h"
#include "image/image_io.h"
#include "raster/stage_times.h"

namespace st {

class CpuRenderer;
class GlRenderer;

enum class Backend { Cpu, Gl };
const char* backend_name(Backend b);

// One named output of a frame besides its image: a render target's level,
// named "<target>" for level 0 and "<target>@<level>" for the others.
struct NamedImage {
    std::string name;
    Image image;
};

struct Rendered {
    Image image;
    std::vector<NamedImage> outputs;  // every level of every named target
    double ms = 0;            // the frame's work, without preparation or read-back
    StageTimes stages;        // CPU backend only
};

class Backends {
public:
    Backends(int threads, GlPlatform gl_platform, std::vector<std::string> glsl_roots);
    ~Backends();

    Rendered render(Backend backend, const Frame& frame);
    // Provenance for EXR metadata of images from `backend`.
    Metadata provenance(Backend backend);
    // GL_RENDERER and GL_VERSION (creates the GL context if needed).
    std::string gl_renderer();
    std::string gl_version();
    // The platform the GL context got (creates it if needed): never Auto.
    GlPlatform gl_platform();

    CpuRenderer& cpu();
    GlRenderer& gl();

private:
    int threads_;
    GlPlatform gl_platform_;
    std::vector<std::string> glsl_roots_;
    std::unique_ptr<CpuRenderer> cpu_;
    std::unique_ptr<GlRenderer> gl_;
};

}  // namespace st
