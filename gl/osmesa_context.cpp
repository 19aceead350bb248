// osmesa_context.cpp: a GL 4.5 core context on llvmpipe through OSMesa
// (libOSMesa.so.8, loaded at run time; Mesa removed it in 25.1).
//
// We render into framebuffer objects, so the OSMesa buffer only has to exist.
// GL entry points come from OSMesaGetProcAddress: OSMesa's own, whatever
// other GL library the process holds (gl_api.h).
#include "gl/gl_context.h"

#if __has_include(<GL/osmesa.h>)
#include <GL/osmesa.h>

#include <vector>

#include "gl/shared_library.h"

namespace st {

namespace {

class OsmesaContext final : public GlContext {
public:
    OsmesaContext() : lib_("OSMesa", "libOSMesa.so.8") {
        create_ = lib_.symbol<decltype(&::OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
        make_current_ = lib_.symbol<decltype(&::OSMesaMakeCurrent)>("OSMesaMakeCurrent");
        destroy_ = lib_.symbol<decltype(&::OSMesaDestroyContext)>("OSMesaDestroyContext");
        const auto get_proc = lib_.symbol<decltype(&::OSMesaGetProcAddress)>("OSMesaGetProcAddress");
        const int attribs[] = {OSMESA_FORMAT,          OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,      0,
                               OSMESA_PROFILE,         OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 5,
                               0};
        context_ = create_(attribs, nullptr);
        if (!context_) throw std::runtime_error("OSMesa: cannot create a GL 4.5 core context");
        api_ = load_gl_api("OSMesa", [&](const char* name) { return get_proc(name); });
        make_current();
    }
    ~OsmesaContext() override { destroy_(context_); }

    void make_current() override {
        if (!make_current_(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSize, kSize))
            throw std::runtime_error("OSMesa: cannot make the context current");
    }
    GlPlatform platform() const override { return GlPlatform::OSMesa; }

private:
    static constexpr int kSize = 16;
    SharedLibrary lib_;
    decltype(&::OSMesaCreateContextAttribs) create_ = nullptr;
    decltype(&::OSMesaMakeCurrent) make_current_ = nullptr;
    decltype(&::OSMesaDestroyContext) destroy_ = nullptr;
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_ = std::vector<unsigned char>(kSize * kSize * 4);
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace st

#else  // no OSMesa headers on the build machine (Mesa 25.1 and later)

#include <stdexcept>

namespace st {

std::unique_ptr<GlContext> make_osmesa_context() {
    throw std::runtime_error("OSMesa: not built in (GL/osmesa.h was missing at build time)");
}

}  // namespace st

#endif
