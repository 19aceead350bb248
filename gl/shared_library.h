// shared_library.h: a library opened at run time (dlopen), kept loaded for
// the life of the process.
//
// Never closed: unloading Mesa and the LLVM it brings while their threads or
// atexit handlers may still run is a known way to crash at exit.
#pragma once

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace st {

class SharedLibrary {
public:
    // Throws std::runtime_error "<what>: cannot load <file> (<dlerror>)".
    SharedLibrary(const char* what, const char* file) : what_(what) {
        handle_ = dlopen(file, RTLD_NOW | RTLD_LOCAL);
        if (!handle_) {
            const char* e = dlerror();
            throw std::runtime_error(what_ + ": cannot load " + file + " (" + (e ? e : "unknown error") + ")");
        }
    }

    // The symbol as `F`; throws when the library lacks it.
    template <class F>
    F symbol(const char* name) const {
        void* p = dlsym(handle_, name);
        if (!p) throw std::runtime_error(what_ + ": no symbol " + name);
        return reinterpret_cast<F>(p);
    }

private:
    std::string what_;
    void* handle_ = nullptr;
};

}  // namespace st
