// bench.cpp: see bench.h.
#include "app/bench.h"

#include <algorithm>
#include <cstdlib>
#include <functional>

#include "app/median.h"
#include "gl/gl_renderer.h"
#include "raster/cpu_renderer.h"

namespace st {

namespace {

FrameStats stats(const std::vector<double>& ms) {
    FrameStats s;
    s.frames = int(ms.size());
    s.ms_median = median(ms);
    s.ms_min = *std::min_element(ms.begin(), ms.end());
    s.ms_max = *std::max_element(ms.begin(), ms.end());
    return s;
}

}  // namespace

void set_llvmpipe_threads(int threads) { setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 0); }

BenchResult bench_scene(const Scene& scene, Backends& backends, int frames, int warmup, CpuRenderer* one_thread) {
    CpuRenderer& cpu = backends.cpu();
    GlRenderer& gl = backends.gl();
    cpu.prepare(scene.frame);
    gl.prepare(scene.frame);
    if (one_thread) one_thread->prepare(scene.frame);
    for (int i = 0; i < warmup; ++i) {
        cpu.execute();
        gl.execute();
        if (one_thread) one_thread->execute();
    }
    std::vector<double> cpu_ms, gl_ms, one_ms, vertex, setup, raster, fragment, output;
    auto run_cpu = [&] {
        const auto t0 = Clock::now();
        cpu.execute();
        cpu_ms.push_back(ms_between(t0, Clock::now()));
        const StageTimes& st = cpu.stage_times();
        vertex.push_back(st.vertex_ms);
        setup.push_back(st.setup_ms);
        raster.push_back(st.raster_ms);
        fragment.push_back(st.fragment_ms);
        output.push_back(st.output_ms);
    };
    auto run_gl = [&] {
        const auto t0 = Clock::now();
        gl.execute();
        gl_ms.push_back(ms_between(t0, Clock::now()));
    };
    auto run_one_thread = [&] {
        const auto t0 = Clock::now();
        one_thread->execute();
        one_ms.push_back(ms_between(t0, Clock::now()));
    };
    // Each renderer goes first, second (and third) equally often.
    std::vector<std::function<void()>> rotation{run_cpu, run_gl};
    if (one_thread) rotation.push_back(run_one_thread);
    for (int f = 0; f < frames; ++f)
        for (size_t k = 0; k < rotation.size(); ++k) rotation[(size_t(f) + k) % rotation.size()]();
    BenchResult r;
    r.scene = scene.name;
    r.width = scene.frame.passes.back().width;
    r.height = scene.frame.passes.back().height;
    r.cpu = stats(cpu_ms);
    r.gl = stats(gl_ms);
    if (one_thread) r.cpu_one_thread = stats(one_ms);
    r.cpu_stages = {median(vertex), median(setup), median(raster), median(fragment), median(output)};
    r.cpu_threads = cpu.threads();
    const char* lp = std::getenv("LP_NUM_THREADS");
    r.gl_threads = lp ? lp : "default";
    return r;
}

nlohmann::json bench_json(const BenchResult& r, Backend backend) {
    const FrameStats& s = backend == Backend::Cpu ? r.cpu : r.gl;
    nlohmann::json j = {{"scene", r.scene},         {"backend", backend_name(backend)},
                        {"width", r.width},         {"height", r.height},
                        {"fps", s.fps()},           {"ms_median", s.ms_median},
                        {"ms_min", s.ms_min},       {"ms_max", s.ms_max},
                        {"frames", s.frames}};
    if (backend == Backend::Cpu) {
        j["threads"] = r.cpu_threads;
        if (r.cpu_one_thread.frames) {
            j["one_thread_ms_median"] = r.cpu_one_thread.ms_median;
            j["scaling"] = r.scaling();
        }
        j["stages"] = {{"vertex", r.cpu_stages.vertex_ms},
                       {"setup_binning", r.cpu_stages.setup_ms},
                       {"rasterization", r.cpu_stages.raster_ms},
                       {"fragment", r.cpu_stages.fragment_ms},
                       {"blend_output", r.cpu_stages.output_ms}};
    } else {
        j["threads"] = r.gl_threads;
    }
    return j;
}

}  // namespace st
