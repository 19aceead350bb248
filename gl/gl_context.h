// gl_context.h: where the GL reference gets a current GL 4.5 core context on
// llvmpipe, and the GL entry points to call on it.
//
// Two platforms give the same llvmpipe: OSMesa, which Mesa removed in 25.1,
// and EGL on Mesa's software device (EGL_MESA_device_software, or the
// surfaceless platform, EGL_MESA_platform_surfaceless). Both are loaded at
// run time (dlopen), so the tool builds and starts on a machine that has
// either; only this interface knows which one it got.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>

#include "gl/gl_api.h"
#include "gl/gl_platform.h"

namespace st {

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void make_current() = 0;
    virtual GlPlatform platform() const = 0;  // never Auto
    const GlApi& gl() const { return api_; }
    std::string renderer() const;  // GL_RENDERER
    std::string version() const;   // GL_VERSION

protected:
    GlApi api_;
};

// A GL 4.5 core context on llvmpipe through `platform`. Auto takes OSMesa
// when its library loads (the platform every measurement so far used) and
// EGL otherwise. Throws std::runtime_error with one line when none can be
// had, saying what each platform lacked.
std::unique_ptr<GlContext> make_gl_context(GlPlatform platform);

// Auto's rule: the first candidate that gives a context; when none does, one
// line with every candidate's reason.
using GlContextFactory = std::unique_ptr<GlContext> (*)();
std::unique_ptr<GlContext> first_gl_context(std::initializer_list<GlContextFactory> candidates);

std::unique_ptr<GlContext> make_osmesa_context();
std::unique_ptr<GlContext> make_egl_context();

}  // namespace st
