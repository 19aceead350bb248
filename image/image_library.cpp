// image_library.cpp: finding and loading libshadertwin_oiio.so (see
// image_library.h).
#include "image/image_library.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace st {

namespace {

constexpr const char* kModule = "libshadertwin_oiio.so";

std::vector<std::string> candidates() {
    std::vector<std::string> out;
    if (const char* given = std::getenv("SHADERTWIN_IMAGE_LIBRARY"); given && *given) {
        out.push_back(given);
        return out;  // when named, only that one
    }
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) out.push_back((exe.parent_path().parent_path() / "lib" / kModule).string());
#ifdef SHADERTWIN_IMAGE_LIBRARY_BUILD_PATH
    out.push_back(SHADERTWIN_IMAGE_LIBRARY_BUILD_PATH);
#endif
    out.push_back(kModule);  // the run path (a user's tool) and LD_LIBRARY_PATH
    return out;
}

const ImageLibrary* load() {
    std::string tried;
    for (const std::string& path : candidates()) {
        // A full path that is not there is no error to report; a name is
        // always tried.
        std::error_code ec;
        if (path.find('/') != std::string::npos && !std::filesystem::exists(path, ec)) continue;
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            tried += (tried.empty() ? "" : "; ") + std::string(why ? why : path);
            continue;
        }
        using Entry = const ImageLibrary* (*)(int);
        const auto entry = reinterpret_cast<Entry>(dlsym(handle, "shadertwin_image_library"));
        const ImageLibrary* library = entry ? entry(kImageLibraryVersion) : nullptr;
        if (library) return library;  // never closed: it lives as long as the process
        tried += (tried.empty() ? "" : "; ") + path + ": not a shadertwin image library of version " +
                 std::to_string(kImageLibraryVersion);
        dlclose(handle);
    }
    throw std::runtime_error("cannot load the image library " + std::string(kModule) + " (OpenImageIO): " +
                             (tried.empty() ? std::string("not found") : tried));
}

}  // namespace

const ImageLibrary& image_library() {
    static const ImageLibrary* const library = load();
    return *library;
}

}  // namespace st
