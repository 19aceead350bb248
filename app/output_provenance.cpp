// output_provenance.cpp: see output_provenance.h.
#include "app/output_provenance.h"

#include "app/provenance.h"
#include "image/file_provenance.h"
#include "simd/lanes.h"

namespace st {

namespace {

std::string compiler() {
#if defined(__clang__)
    return "clang " __clang_version__;
#elif defined(__GNUC__)
    return "GCC " __VERSION__;
#else
    return "unknown compiler";
#endif
}

std::string lanes() {
    std::string isa = "generic";
#if defined(__AVX512F__)
    isa = "avx512";
#elif defined(__AVX2__)
    isa = "avx2";
#endif
    return isa + ", " + std::to_string(simd::kLanes) + " lanes";
}

void publish(FileProvenance p) {
    const auto& a = p.attributes;
    std::string line = "shadertwin " + a.at("version") + " (" + a.at("commit") + "), " + a.at("compiler") + ", " +
                       a.at("lanes") + "; CPU flags " + a.at("cpu_flags");
    if (a.count("gl_reference")) line += "; reference " + a.at("gl_reference");
    p.line = line;
    set_file_provenance(std::move(p));
}

}  // namespace

void record_build_provenance() {
    FileProvenance p;
    p.attributes = {{"version", shadertwin_version()},
                    {"commit", shadertwin_git_commit()},
                    {"compiler", compiler()},
                    {"lanes", lanes()},
                    {"cpu_flags", cpu_flags()}};
    publish(std::move(p));
}

void record_gl_provenance(const std::string& gl_renderer, const std::string& gl_version,
                          const std::string& gl_platform) {
    FileProvenance p = file_provenance();
    if (p.attributes.empty()) {
        record_build_provenance();
        p = file_provenance();
    }
    p.attributes["mesa"] = mesa_version(gl_version);
    p.attributes["gl_reference"] = gl_renderer + ", Mesa " + mesa_version(gl_version) + ", " + gl_platform;
    publish(std::move(p));
}

std::string provenance_line() { return file_provenance().line; }

}  // namespace st
