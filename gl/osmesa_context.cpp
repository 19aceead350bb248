// osmesa_context.cpp: a GL 4.5 core context on llvmpipe through OSMesa.
//
// We render into framebuffer objects, so the OSMesa buffer only has to exist.
// Link libOSMesa alone: glvnd's libGL beside it takes the GL entry points.
#include "gl/gl_context.h"

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

namespace st {

namespace {

class OsmesaContext final : public GlContext {
public:
    OsmesaContext() {
        const int attribs[] = {OSMESA_FORMAT,          OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,      0,
                               OSMESA_PROFILE,         OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 5,
                               0};
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!context_) throw std::runtime_error("OSMesa: cannot create a GL 4.5 core context");
        make_current();
    }
    ~OsmesaContext() override { OSMesaDestroyContext(context_); }

    void make_current() override {
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSize, kSize))
            throw std::runtime_error("OSMesa: cannot make the context current");
    }
    std::string renderer() const override { return get(GL_RENDERER); }
    std::string version() const override { return get(GL_VERSION); }

private:
    static std::string get(GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? reinterpret_cast<const char*>(s) : "";
    }
    static constexpr int kSize = 16;
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_ = std::vector<unsigned char>(kSize * kSize * 4);
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace st
