// provenance.cpp: see provenance.h.
#include "app/provenance.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#ifndef SHADERTWIN_VERSION
#define SHADERTWIN_VERSION "unknown"
#endif

namespace st {

std::string shadertwin_version() { return SHADERTWIN_VERSION; }

std::string cpu_flags() {
    static const std::string flags = [] {
        const std::set<std::string> wanted = {"sse4_1", "sse4_2", "avx", "avx2", "fma", "f16c", "avx512f"};
        std::ifstream in("/proc/cpuinfo");
        std::string line;
        while (std::getline(in, line)) {
            if (line.rfind("flags", 0) != 0) continue;
            std::istringstream words(line.substr(line.find(':') + 1));
            std::string w, out;
            while (words >> w)
                if (wanted.count(w)) out += (out.empty() ? "" : " ") + w;
            return out;
        }
        return std::string();
    }();
    return flags;
}

std::string mesa_version(const std::string& gl_version) {
    std::smatch m;
    return std::regex_search(gl_version, m, std::regex("Mesa ([0-9][0-9.]*)")) ? m[1].str() : "";
}

std::string llvm_version(const std::string& gl_renderer) {
    std::smatch m;
    return std::regex_search(gl_renderer, m, std::regex("LLVM ([0-9][0-9.]*)")) ? m[1].str() : "";
}

}  // namespace st
