// gl_context.h: where the GL reference gets a current GL 4.5 core context.
//
// Only this interface knows about OSMesa. OSMesa was removed from Mesa in
// 25.1; EGL with EGL_MESA_platform_surfaceless is the replacement, and it
// goes behind the same interface.
#pragma once

#include <memory>
#include <string>

namespace st {

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void make_current() = 0;
    virtual std::string renderer() const = 0;   // GL_RENDERER
    virtual std::string version() const = 0;    // GL_VERSION
};

// A GL 4.5 core context on llvmpipe through OSMesa. Throws std::runtime_error
// with one line when none can be had.
std::unique_ptr<GlContext> make_osmesa_context();

}  // namespace st
