// gl_platform.h: which library gives the GL reference its llvmpipe context.
#pragma once

#include <string>

namespace st {

// OSMesa (removed from Mesa in 25.1) or EGL without a window system; Auto
// takes OSMesa when its library loads and EGL otherwise (gl_context.h).
enum class GlPlatform { Auto, OSMesa, Egl };

// "auto", "osmesa" or "egl"; throws std::invalid_argument otherwise.
GlPlatform parse_gl_platform(const std::string& name);
const char* gl_platform_name(GlPlatform p);

}  // namespace st
