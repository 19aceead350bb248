// gl_api.cpp: see gl_api.h.
#include "gl/gl_api.h"

#include <stdexcept>
#include <string>

namespace st {

GlApi load_gl_api(const char* platform, const GlProcLookup& lookup) {
    GlApi api;
#define ST_GL_LOAD(name)                                                                                 \
    if (auto* f = lookup("gl" #name))                                                                    \
        api.name = reinterpret_cast<decltype(api.name)>(f);                                              \
    else                                                                                                 \
        throw std::runtime_error(std::string(platform) + ": no entry point gl" #name);
    ST_GL_FUNCTIONS(ST_GL_LOAD)
#undef ST_GL_LOAD
    return api;
}

}  // namespace st
