// bench.h: frames per second of one scene on both backends, measured the
// same way for both (issue rules, docs/performance.md):
// - a frame runs from the start of its work to a finished image in memory
//   (glFinish on GL); shader compilation, asset generation and read-back are
//   outside it, per-frame host work (the thin-slab host variant) inside;
// - both backends are prepared once, warmed up, then alternate frame by
//   frame (which one goes first alternates too), so both see the same
//   machine; statistics are medians.
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
    StageTimes cpu_stages;  // per-stage medians over the frames
    int cpu_threads = 0;
    std::string gl_threads;  // LP_NUM_THREADS as llvmpipe saw it
};

BenchResult bench_scene(const Scene& scene, Backends& backends, int frames, int warmup);

// One JSON object per backend, in the shape `bench --json` prints.
nlohmann::json bench_json(const BenchResult& r, Backend backend);

// Makes llvmpipe use `threads` threads unless LP_NUM_THREADS is already set;
// must run before the GL context exists.
void set_llvmpipe_threads(int threads);

}  // namespace st
