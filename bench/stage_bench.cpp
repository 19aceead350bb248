// stage_bench.cpp: Google Benchmark micro-benchmarks of the CPU pipeline's
// stages, one at a time, with items-per-second counters (vertices,
// triangles, pixels, samples). Whole frames: frame_bench in this folder.
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "frame/frame.h"
#include "shading/program.h"
#include "raster/attribute_setup.h"
#include "raster/fragment_inputs.h"
#include "raster/output_merge.h"
#include "shading/block_layout.h"
#include "texture/sampler2d.h"
#include "raster/tile_raster.h"
#include "raster/triangle_setup.h"
#include "raster/viewport.h"

namespace st {
namespace {

std::vector<glm::vec4> random_clip_positions(int n) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), w(0.5f, 4.0f);
    std::vector<glm::vec4> out;
    for (int i = 0; i < n; ++i) {
        const float ww = w(rng);
        out.emplace_back(u(rng) * ww, u(rng) * ww, u(rng) * ww, ww);
    }
    return out;
}

void BM_ViewportTransform(benchmark::State& state) {
    const auto pos = random_clip_positions(4096);
    const Viewport vp{0, 0, 512, 512, 0, 1};
    for (auto _ : state)
        for (const auto& p : pos) benchmark::DoNotOptimize(to_window(p, vp));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(pos.size()));
    state.SetLabel("vertices");
}
BENCHMARK(BM_ViewportTransform);

// Setup of triangles about 20 pixels across with 3 varying slots.
void BM_TriangleSetup(benchmark::State& state) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(10.0f, 500.0f), d(-20.0f, 20.0f);
    const glm::vec4 varyings[3][3] = {};
    std::vector<SetupVertex> verts;
    for (int i = 0; i < 3000; ++i) {
        const float x = u(rng), y = u(rng);
        verts.push_back({WindowPos{x + d(rng), y + d(rng), 0.5f, 1.0f}, varyings[i % 3]});
    }
    std::vector<Plane> planes;
    planes.reserve(1 << 16);
    for (auto _ : state) {
        planes.clear();
        for (size_t i = 0; i + 2 < verts.size(); i += 3) {
            SetupTriangle tri;
            benchmark::DoNotOptimize(setup_triangle(verts[i], verts[i + 1], verts[i + 2], 3, 512, 512, tri, planes));
        }
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * 1000);
    state.SetLabel("triangles");
}
BENCHMARK(BM_TriangleSetup);

// Coverage of one 64x64 tile by a triangle covering about half of it.
void BM_RasterizeTile(benchmark::State& state) {
    const glm::vec4 none[1] = {};
    SetupTriangle tri;
    std::vector<Plane> planes;
    setup_triangle({WindowPos{0.3f, 0.2f, 0.5f, 1}, none}, {WindowPos{63.7f, 1.1f, 0.5f, 1}, none},
                   {WindowPos{2.2f, 63.9f, 0.5f, 1}, none}, 0, 64, 64, tri, planes);
    std::vector<BlockCoverage> blocks;
    long pixels = 0;
    for (auto _ : state) {
        blocks.clear();
        rasterize_in_tile(tri, TileRect{0, 0, 64, 64}, blocks);
        benchmark::DoNotOptimize(blocks.data());
        pixels += 64 * 64;
    }
    state.SetItemsProcessed(pixels);
    state.SetLabel("tile pixels");
}
BENCHMARK(BM_RasterizeTile);

// Perspective-correct interpolation of 3 varying slots for one whole 4x4
// block (kBlockLanes / kLanes twin inputs).
void BM_InterpolateBlock(benchmark::State& state) {
    std::vector<Plane> planes(2 + 12, Plane{0.5f, 0.01f, 0.02f});
    FragmentLanes lanes;
    LaneGroup groups[2] = {{100, 200, 0, 0xff}, {100, 200, 1, 0xff}};
    for (auto _ : state)
        for (int part = 0; part < kBlockLanes / kLanes; ++part) {
            interpolate_lanes(planes.data(), 3, ~0u, groups + part, true, lanes);
            benchmark::DoNotOptimize(lanes);
        }
    state.SetItemsProcessed(int64_t(state.iterations()) * kBlockLanes);
    state.SetLabel("pixels");
}
BENCHMARK(BM_InterpolateBlock);

// Depth-free blending of kLanes lanes into one framebuffer group pair, as
// the output stage does it (load, blend, select, store).
void BM_Blend(benchmark::State& state, BlendMode mode) {
    alignas(64) float colour[2][4 * kGroupLanes], depth[2][kGroupLanes] = {};
    for (auto& g : colour) std::fill(std::begin(g), std::end(g), 0.5f);
    const Vec4 src(Float(0.1f), Float(0.2f), Float(0.3f), Float(0.4f));
    DrawState ds;
    ds.blend = mode;
    const float* in_colour[2] = {colour[0], colour[1]};
    const float* in_depth[2] = {depth[0], depth[1]};
    float* out_colour[2] = {colour[0], colour[1]};
    float* out_depth[2] = {depth[0], depth[1]};
    for (auto _ : state) {
        merge_lanes(ds, false, src, Float(0.5f), Mask(true), in_colour, in_depth, out_colour, out_depth);
        benchmark::DoNotOptimize(colour);
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * kLanes);
    state.SetLabel("pixels");
}
BENCHMARK_CAPTURE(BM_Blend, none, BlendMode::None);
BENCHMARK_CAPTURE(BM_Blend, one_src_alpha, BlendMode::OneSrcAlpha);
BENCHMARK_CAPTURE(BM_Blend, src_alpha_one_minus_src_alpha, BlendMode::SrcAlphaOneMinusSrcAlpha);

Texture noise_texture(TextureFormat format, TextureFilter filter) {
    Texture t;
    t.format = format;
    t.set_filter(filter);
    t.width = t.height = 256;
    std::mt19937 rng(1);
    for (int i = 0; i < 256 * 256 * 4; ++i) {
        if (format == TextureFormat::RGBA8) t.texels8.push_back(uint8_t(rng()));
        else t.texels32.push_back(float(rng() & 0xffff) / 65536.0f);
    }
    return t;
}

// texture() on all lanes at once. "random": coordinates anywhere in
// [-1, 2)^2 (every lane its own texels); "unscaled": a 4x4 block mapped
// texel for texel, as a full-screen quad over a texture of the screen's size
// reads it.
void BM_Sample(benchmark::State& state, TextureFormat format, TextureFilter filter, bool random) {
    const Texture t = noise_texture(format, filter);
    const Sampler2D s(t);
    std::vector<Vec2> uv(4096 / kLanes);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 2.0f);
    for (size_t i = 0; i < uv.size(); ++i)
        for (int lane = 0; lane < kLanes; ++lane) {
            const int block = int(i) % 4096, bx = block % 64 * 4, by = block / 64 % 64 * 4;
            const float x = random ? u(rng) : (float(bx + block_lane_x(lane)) + 0.5f) / 256.0f;
            const float y = random ? u(rng) : (float(by + block_lane_y(lane % 16)) + 0.5f) / 256.0f;
            uv[i].x.set(lane, x);
            uv[i].y.set(lane, y);
        }
    for (auto _ : state)
        for (const auto& c : uv) benchmark::DoNotOptimize(s.sample(c));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(uv.size()) * kLanes);
    state.SetLabel("samples");
}
BENCHMARK_CAPTURE(BM_Sample, rgba8_linear_random, TextureFormat::RGBA8, TextureFilter::Linear, true);
BENCHMARK_CAPTURE(BM_Sample, rgba8_linear_unscaled, TextureFormat::RGBA8, TextureFilter::Linear, false);
BENCHMARK_CAPTURE(BM_Sample, rgba8_nearest_random, TextureFormat::RGBA8, TextureFilter::Nearest, true);
BENCHMARK_CAPTURE(BM_Sample, rgba32f_linear_random, TextureFormat::RGBA32F, TextureFilter::Linear, true);
BENCHMARK_CAPTURE(BM_Sample, rgba32f_linear_unscaled, TextureFormat::RGBA32F, TextureFilter::Linear, false);
BENCHMARK_CAPTURE(BM_Sample, rgba32f_nearest_random, TextureFormat::RGBA32F, TextureFilter::Nearest, true);

}  // namespace
}  // namespace st
