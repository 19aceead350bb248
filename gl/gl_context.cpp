// gl_context.cpp: choosing a GL platform (see gl_context.h).
#include "gl/gl_context.h"

#include <stdexcept>

namespace st {

GlPlatform parse_gl_platform(const std::string& name) {
    if (name == "auto") return GlPlatform::Auto;
    if (name == "osmesa") return GlPlatform::OSMesa;
    if (name == "egl") return GlPlatform::Egl;
    throw std::invalid_argument("GL platform '" + name + "' is not auto, osmesa or egl");
}

const char* gl_platform_name(GlPlatform p) {
    switch (p) {
        case GlPlatform::Auto: return "auto";
        case GlPlatform::OSMesa: return "osmesa";
        case GlPlatform::Egl: return "egl";
    }
    return "auto";
}

namespace {

std::string gl_string(const GlApi& gl, GLenum name) {
    const GLubyte* s = gl.GetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

std::string GlContext::renderer() const { return gl_string(api_, GL_RENDERER); }
std::string GlContext::version() const { return gl_string(api_, GL_VERSION); }

std::unique_ptr<GlContext> make_gl_context(GlPlatform platform) {
    switch (platform) {
        case GlPlatform::OSMesa: return make_osmesa_context();
        case GlPlatform::Egl: return make_egl_context();
        case GlPlatform::Auto: break;
    }
    return first_gl_context({make_osmesa_context, make_egl_context});
}

std::unique_ptr<GlContext> first_gl_context(std::initializer_list<GlContextFactory> candidates) {
    std::string why;
    for (GlContextFactory make : candidates) {
        try {
            return make();
        } catch (const std::exception& e) {
            why += (why.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    throw std::runtime_error("no GL platform: " + (why.empty() ? std::string("none tried") : why));
}

}  // namespace st
