// kernel_bench.cpp: every registered twin, vertex and fragment, bound with
// the uniforms and textures of the first built-in scene that draws with it,
// with vertices/s or pixels/s counters; and whole CPU frames of each
// built-in thin-slab scene (pixels/s of the target).
#include <deque>
#include <memory>

#include <benchmark/benchmark.h>

#include "kernels/registry.h"
#include "raster/cpu_renderer.h"
#include "shading/block_layout.h"
#include "texture/sampler2d.h"
#include "scene/scene.h"

namespace st {
namespace {

struct Binding {
    Scene scene;
    const DrawCall* draw = nullptr;
    std::deque<Sampler2D> samplers;
    Bindings bindings;
};

// The first built-in scene with a draw whose vertex (or fragment) stage is
// `name`; the coverage stage is found in the scenes' coverage passes.
std::unique_ptr<Binding> find_binding(const std::string& name, bool vertex) {
    for (const auto& scene_name : builtin_scene_names()) {
        auto b = std::make_unique<Binding>();
        b->scene = load_scene(scene_name, {});
        if (name == "coverage") b->scene.frame = coverage_frame(b->scene.frame);
        for (const Pass& pass : b->scene.frame.passes)
            for (const DrawCall& d : pass.draws)
                if ((vertex ? d.vertex : d.fragment) == name) {
                    b->draw = &d;
                    b->bindings.uniforms = &d.uniforms;
                    for (const Texture& t : d.textures) {
                        b->bindings.samplers.push_back(&b->samplers.emplace_back(t));
                        b->bindings.sampler_names.push_back(t.sampler);
                    }
                    return b;
                }
    }
    return nullptr;
}

void BM_VertexTwin(benchmark::State& state, std::string name) {
    auto b = find_binding(name, true);
    if (!b) return state.SkipWithError("no built-in scene uses this twin");
    auto twin = make_vertex_twin(name);
    twin->bind(b->bindings);
    const VertexArray& va = b->draw->vertices;
    VertexOut out;
    for (auto _ : state)
        for (int v = 0; v < va.vertex_count(); ++v) {
            twin->run(va.vertex(v), out);
            benchmark::DoNotOptimize(out);
        }
    state.SetItemsProcessed(int64_t(state.iterations()) * va.vertex_count());
    state.SetLabel("vertices, from " + b->scene.name);
}

// Quads whose inputs mix the draw's first triangle's varyings (after its
// vertex twin) at fixed barycentric positions: realistic values, no raster.
void BM_FragmentTwin(benchmark::State& state, std::string name) {
    auto b = find_binding(name, false);
    if (!b) return state.SkipWithError("no built-in scene uses this twin");
    auto vertex = make_vertex_twin(b->draw->vertex);
    auto fragment = make_fragment_twin(name);
    vertex->bind(b->bindings);
    fragment->bind(b->bindings);
    VertexOut tri[3];
    for (int k = 0; k < 3; ++k) vertex->run(b->draw->vertices.vertex(int(b->draw->indices[size_t(k)])), tri[k]);
    std::vector<FragmentLanes> inputs(1024 / kLanes);
    auto set = [](Vec4& v, int lane, const glm::vec4& x) {
        v.x.set(lane, x.x);
        v.y.set(lane, x.y);
        v.z.set(lane, x.z);
        v.w.set(lane, x.w);
    };
    for (size_t q = 0; q < inputs.size(); ++q)
        for (int lane = 0; lane < kLanes; ++lane) {
            const size_t i = q * kLanes + size_t(lane);
            const float a = float(i % 97) / 97.0f, c = float(i / 4 % 13) / 26.0f;
            for (int s = 0; s < vertex->varying_count(); ++s)
                set(inputs[q].varyings[size_t(s)], lane,
                    tri[0].varyings[size_t(s)] * (1 - a - c) + tri[1].varyings[size_t(s)] * a + tri[2].varyings[size_t(s)] * c);
            set(inputs[q].frag_coord, lane, glm::vec4(float(block_lane_x(lane % 16)) + 0.5f, float(block_lane_y(lane % 16)) + 0.5f, 0.5f, 1.0f));
            inputs[q].covered = Mask(true);
        }
    FragmentResult out;
    for (auto _ : state)
        for (const auto& in : inputs) {
            fragment->shade(in, out);
            benchmark::DoNotOptimize(out);
        }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(inputs.size()) * kLanes);
    state.SetLabel("pixels, from " + b->scene.name);
}

void BM_CpuFrame(benchmark::State& state, std::string scene_name, int threads) {
    const Scene scene = load_scene(scene_name, {});
    CpuRenderer cpu(threads, twins());
    cpu.prepare(scene.frame);
    for (auto _ : state) cpu.execute();
    const auto& pass = scene.frame.passes.back();
    state.SetItemsProcessed(int64_t(state.iterations()) * pass.width * pass.height);
    state.SetLabel("target pixels");
}

const bool registered = [] {
    for (const auto& n : vertex_twin_names())
        benchmark::RegisterBenchmark(("BM_VertexTwin/" + n).c_str(), BM_VertexTwin, n);
    for (const auto& n : fragment_twin_names())
        benchmark::RegisterBenchmark(("BM_FragmentTwin/" + n).c_str(), BM_FragmentTwin, n);
    for (const auto& s : builtin_scene_names())
        if ((s.rfind("thin-slab-", 0) == 0 && s.find("sweep") == std::string::npos) || s.rfind("relief-", 0) == 0 ||
            s.rfind("profile-", 0) == 0)
            for (int threads : {1, 2})
                benchmark::RegisterBenchmark(("BM_CpuFrame/" + s + "/threads:" + std::to_string(threads)).c_str(),
                                             BM_CpuFrame, s, threads)
                    ->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
}  // namespace st
