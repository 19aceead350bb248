// egl_context.cpp: a GL 4.5 core context on llvmpipe through EGL, with no
// window system (libEGL.so.1, loaded at run time).
//
// The display is Mesa's software device when the EGL library can list
// devices (EGL_EXT_device_enumeration + EGL_MESA_device_software), so a
// machine with a GPU still gives llvmpipe; else the surfaceless platform
// (EGL_MESA_platform_surfaceless). The context has no config and no surface
// (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): we render into
// framebuffer objects. A context that is not llvmpipe is refused: it would not
// be the reference. GL entry points come from eglGetProcAddress (gl_api.h);
// with glvnd these are dispatch stubs bound to whichever context is current.
#include "gl/gl_context.h"

#if __has_include(<EGL/egl.h>)
// No X11 types in EGL's platform header: we have no window system.
#define EGL_NO_X11 1
#define MESA_EGL_NO_X11_HEADERS 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <sstream>
#include <vector>

#include "gl/shared_library.h"

namespace st {

namespace {

bool has_extension(const char* list, const char* name) {
    if (!list) return false;
    std::istringstream words(list);
    std::string word;
    while (words >> word)
        if (word == name) return true;
    return false;
}

class EglContext final : public GlContext {
public:
    EglContext() : lib_("EGL", "libEGL.so.1") {
        get_proc_ = lib_.symbol<decltype(&::eglGetProcAddress)>("eglGetProcAddress");
        const auto query_string = lib_.symbol<decltype(&::eglQueryString)>("eglQueryString");
        const auto initialize = lib_.symbol<decltype(&::eglInitialize)>("eglInitialize");
        const auto bind_api = lib_.symbol<decltype(&::eglBindAPI)>("eglBindAPI");
        const auto create_context = lib_.symbol<decltype(&::eglCreateContext)>("eglCreateContext");
        const auto get_error = lib_.symbol<decltype(&::eglGetError)>("eglGetError");
        make_current_ = lib_.symbol<decltype(&::eglMakeCurrent)>("eglMakeCurrent");
        destroy_context_ = lib_.symbol<decltype(&::eglDestroyContext)>("eglDestroyContext");

        const char* client = query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        const auto get_platform_display =
            extension<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
        if (!has_extension(client, "EGL_EXT_platform_base") || !get_platform_display)
            throw std::runtime_error("EGL: no EGL_EXT_platform_base");
        display_ = software_device_display(client, get_platform_display);
        if (display_ == EGL_NO_DISPLAY && has_extension(client, "EGL_MESA_platform_surfaceless"))
            display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY)
            throw std::runtime_error("EGL: neither Mesa's software device nor the surfaceless platform");
        EGLint major = 0, minor = 0;
        if (!initialize(display_, &major, &minor)) throw std::runtime_error("EGL: cannot initialise the display");
        const char* display_extensions = query_string(display_, EGL_EXTENSIONS);
        for (const char* needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context"})
            if (!has_extension(display_extensions, needed))
                throw std::runtime_error(std::string("EGL: the display lacks ") + needed);
        if (!bind_api(EGL_OPENGL_API)) throw std::runtime_error("EGL: no desktop OpenGL API");
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                  EGL_NONE};
        context_ = create_context(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
        if (context_ == EGL_NO_CONTEXT) {
            std::ostringstream why;
            why << "EGL: cannot create a GL 4.5 core context (error 0x" << std::hex << get_error() << ")";
            throw std::runtime_error(why.str());
        }
        try {
            make_current();
            api_ = load_gl_api("EGL", [&](const char* name) { return get_proc_(name); });
            if (const std::string r = renderer(); r.rfind("llvmpipe", 0) != 0)
                throw std::runtime_error("EGL: the context runs on '" + r + "', not llvmpipe");
        } catch (...) {
            release();
            throw;
        }
    }
    ~EglContext() override { release(); }

    void make_current() override {
        if (!make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("EGL: cannot make the context current");
    }
    GlPlatform platform() const override { return GlPlatform::Egl; }

private:
    // Not eglTerminate: another renderer in this process may share the
    // display, and EGL does not count initialisations.
    void release() {
        make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        destroy_context_(display_, context_);
    }

    template <class F>
    F extension(const char* name) const {
        return reinterpret_cast<F>(get_proc_(name));
    }

    // Mesa's software device among the listed ones, or EGL_NO_DISPLAY.
    EGLDisplay software_device_display(const char* client, PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display) {
        if (!has_extension(client, "EGL_EXT_device_enumeration") ||
            !has_extension(client, "EGL_EXT_platform_device"))
            return EGL_NO_DISPLAY;
        const auto query_devices = extension<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
        const auto query_device_string = extension<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
        EGLint count = 0;
        if (!query_devices || !query_device_string || !query_devices(0, nullptr, &count) || count <= 0)
            return EGL_NO_DISPLAY;
        std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
        if (!query_devices(count, devices.data(), &count)) return EGL_NO_DISPLAY;
        for (EGLint i = 0; i < count; ++i)
            if (has_extension(query_device_string(devices[size_t(i)], EGL_EXTENSIONS), "EGL_MESA_device_software"))
                return get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[size_t(i)], nullptr);
        return EGL_NO_DISPLAY;
    }

    SharedLibrary lib_;
    decltype(&::eglGetProcAddress) get_proc_ = nullptr;
    decltype(&::eglMakeCurrent) make_current_ = nullptr;
    decltype(&::eglDestroyContext) destroy_context_ = nullptr;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace st

#else  // no EGL headers on the build machine

#include <stdexcept>

namespace st {

std::unique_ptr<GlContext> make_egl_context() {
    throw std::runtime_error("EGL: not built in (EGL/egl.h was missing at build time)");
}

}  // namespace st

#endif
