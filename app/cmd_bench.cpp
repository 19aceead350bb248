// cmd_bench.cpp: `bench`, frames per second on both backends (app/bench.h
// says how a frame is measured).
#include "app/tool_data.h"
#include "app/progress.h"
#include "app/memory_budget.h"
#include "app/pass_times.h"
#include "scene/profile_material.h"
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/bench.h"
#include "app/commands.h"
#include "app/json_text.h"
#include "kernels/registry.h"
#include "raster/cpu_renderer.h"

namespace st {

int cmd_bench(const std::vector<std::string>& names, int frames, bool json, bool scaling, bool per_pass,
              const CommonOptions& common) {
    std::vector<Scene> scenes;
    for (const auto& n : names) scenes.push_back(load_scene(n, common.overrides));
    check_memory(scenes, MemoryUse::BothBackends, common.max_memory);
    set_llvmpipe_threads(common.threads);
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    std::unique_ptr<CpuRenderer> one_thread;
    if (scaling) one_thread = std::make_unique<CpuRenderer>(1, twins());
    if (!json)
        std::printf("%-30s %9s %9s %9s %7s %24s %24s | %7s %7s %7s %8s %7s%s\n", "scene", "size", "cpu fps", "gl fps",
                    "cpu/gl", "cpu ms med/min/max", "gl ms med/min/max", "vertex", "setup", "raster", "fragment",
                    "output", scaling ? " | 1-thread ms  scaling" : "");
    Progress progress("bench", scenes.size());
    for (size_t i = 0; i < scenes.size(); ++i) {
        progress.step(scenes[i].name);
        const BenchResult r = bench_scene(scenes[i], backends, frames, std::max(2, frames / 10), one_thread.get());
        if (json) {
            std::cout << json_text(bench_json(r, Backend::Cpu)) << "\n" << json_text(bench_json(r, Backend::Gl)) << std::endl;
            continue;
        }
        char size[32], cpu_ms[64], gl_ms[64];
        std::snprintf(size, sizeof size, "%dx%d", r.width, r.height);
        std::snprintf(cpu_ms, sizeof cpu_ms, "%.3f/%.3f/%.3f", r.cpu.ms_median, r.cpu.ms_min, r.cpu.ms_max);
        std::snprintf(gl_ms, sizeof gl_ms, "%.3f/%.3f/%.3f", r.gl.ms_median, r.gl.ms_min, r.gl.ms_max);
        std::printf("%-30s %9s %9.1f %9.1f %7.2f %24s %24s | %7.3f %7.3f %7.3f %8.3f %7.3f", r.scene.c_str(), size,
                    r.cpu.fps(), r.gl.fps(), r.cpu.fps() / r.gl.fps(), cpu_ms, gl_ms, r.cpu_stages.vertex_ms,
                    r.cpu_stages.setup_ms, r.cpu_stages.raster_ms, r.cpu_stages.fragment_ms, r.cpu_stages.output_ms);
        if (scaling) std::printf(" | %11.3f %8.2f", r.cpu_one_thread.ms_median, r.scaling());
        std::printf("\n");
        if (per_pass && scenes[i].frame.passes.size() > 1)
            for (const PassTime& p : measure_pass_times(backends, scenes[i].frame, frames))
                std::printf("  pass %-23s cpu %8.3f ms  gl %8.3f ms  cpu/gl fps %5.2f\n", p.name.c_str(), p.cpu_ms,
                            p.gl_ms, p.cpu_ms > 0 ? p.gl_ms / p.cpu_ms : 0.0);
        std::fflush(stdout);
    }
    if (!json)
        std::printf("frames %d per backend (medians), cpu threads %d, LP_NUM_THREADS %s\n", frames, common.threads,
                    std::getenv("LP_NUM_THREADS") ? std::getenv("LP_NUM_THREADS") : "unset");
    if (per_pass && !json)
        for (const std::string& line : profile_build_log()) std::printf("profile build (not in any frame): %s\n", line.c_str());
    return 0;
}

}  // namespace st
