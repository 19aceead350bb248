// backends.cpp: see backends.h.
#include "app/backends.h"

#include "app/output_provenance.h"
#include "app/provenance.h"
#include "gl/gl_renderer.h"
#include "kernels/registry.h"
#include "raster/cpu_renderer.h"

namespace st {

const char* backend_name(Backend b) { return b == Backend::Cpu ? "cpu" : "gl"; }

Backends::Backends(int threads, GlPlatform gl_platform, std::vector<std::string> glsl_roots)
    : threads_(threads), gl_platform_(gl_platform), glsl_roots_(std::move(glsl_roots)) {}
Backends::~Backends() = default;

CpuRenderer& Backends::cpu() {
    if (!cpu_) cpu_ = std::make_unique<CpuRenderer>(threads_, twins());
    return *cpu_;
}

GlRenderer& Backends::gl() {
    if (!gl_) {
        gl_ = std::make_unique<GlRenderer>(glsl_roots_, gl_platform_);
        record_gl_provenance(gl_->renderer(), gl_->version(), gl_platform_name(gl_->platform()));
    }
    return *gl_;
}

std::string Backends::gl_renderer() { return gl().renderer(); }
std::string Backends::gl_version() { return gl().version(); }
GlPlatform Backends::gl_platform() { return gl().platform(); }

namespace {

template <class Renderer>
void read_outputs(Renderer& r, const Frame& frame, Rendered& out) {
    out.image = r.read_back();
    for (const RenderTarget& t : frame.targets)
        for (int level = 0; level < t.levels; ++level)
            out.outputs.push_back({t.name + (level ? "@" + std::to_string(level) : ""), r.read_back(t.name, level)});
}

}  // namespace

Rendered Backends::render(Backend backend, const Frame& frame) {
    Rendered out;
    if (backend == Backend::Cpu) {
        CpuRenderer& r = cpu();
        r.prepare(frame);
        const auto t0 = Clock::now();
        r.execute();
        out.ms = ms_between(t0, Clock::now());
        out.stages = r.stage_times();
        read_outputs(r, frame, out);
    } else {
        GlRenderer& r = gl();
        r.prepare(frame);
        const auto t0 = Clock::now();
        r.execute();
        out.ms = ms_between(t0, Clock::now());
        read_outputs(r, frame, out);
    }
    return out;
}

Metadata Backends::provenance(Backend backend) {
    Metadata m;
    m["backend"] = backend_name(backend);
    m["version"] = shadertwin_version();
    m["cpu_flags"] = cpu_flags();
    if (backend == Backend::Cpu) {
        m["renderer"] = "shadertwin cpu rasterizer, " + std::to_string(cpu().threads()) + " threads";
    } else {
        m["renderer"] = gl_renderer();
        m["gl_version"] = gl_version();
        m["gl_platform"] = gl_platform_name(gl_platform());
    }
    return m;
}

}  // namespace st
