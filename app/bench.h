// bench.h: frames per second of one scene on both backends, measured the
// same way for both (issue rules, docs/performance.md):
// - a frame runs from the start of its work to a finished image in memory
//   (glFinish on GL); shader compilation, asset generation and read-back are
//   outside it, per-frame host work (the thin-slab host variant) inside;
// - both backends are prepared once, warmed up, then alternate frame by
//   frame (which one goes first alternates too), so both see the same
//   machine; statistics are medians;
// - with a second, one-thread CPU renderer (`bench --scaling`), its frames
//   join the rotation, so that the 1 -> N thread scaling compares frames
//   run side by side in time rather than two runs seconds apart, which on a
//   shared host differ by more than the effect measured.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "app/backends.h"
#include "scene/scene.h"

namespace st {

struct FrameStats {
    int frames = 0;
    double ms_median = 0, ms_min = 0, ms_max = 0;
    double fps() const { return ms_median > 0 ? 1000.0 / ms_median : 0.0; }
};

struct BenchResult {
    std::string scene;
    int width = 0, height = 0;
    FrameStats cpu, gl;
    FrameStats cpu_one_thread;  // frames == 0 unless measured (--scaling)
    StageTimes cpu_stages;  // per-stage medians over the frames
    int cpu_threads = 0;
    std::string gl_threads;  // LP_NUM_THREADS as llvmpipe saw it
    // Median one-thread frame time over the median N-thread one, 0 when not measured.
    double scaling() const {
        return cpu_one_thread.frames && cpu.ms_median > 0 ? cpu_one_thread.ms_median / cpu.ms_median : 0.0;
    }
};

// `one_thread`, when given, is a CpuRenderer with one thread whose frames
// are interleaved with the others' (cpu_one_thread).
BenchResult bench_scene(const Scene& scene, Backends& backends, int frames, int warmup,
                        CpuRenderer* one_thread = nullptr);

// One JSON object per backend, in the shape `bench --json` prints.
nlohmann::json bench_json(const BenchResult& r, Backend backend);

// Makes llvmpipe use `threads` threads unless LP_NUM_THREADS is already set;
// must run before the GL context exists.
void set_llvmpipe_threads(int threads);

}  // namespace st
