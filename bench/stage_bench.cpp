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
#include "texture/mip_generation.h"
#include "texture/sampler2d.h"
#include "texture/sampler_cube.h"
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
            benchmark::DoNotOptimize(setup_triangle(verts[i], verts[i + 1], verts[i + 2], 3, Interpolations{}, 512, 512, tri, planes));
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
                   {WindowPos{2.2f, 63.9f, 0.5f, 1}, none}, 0, Interpolations{}, 64, 64, tri, planes);
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

// Coverage of one 64x64 tile by a mesh of small triangles (7x7-pixel cells
// split in two, off the pixel grid): most blocks are partly covered, so
// this times the per-lane edge test that a large triangle rarely reaches.
void BM_RasterizeSmallTriangles(benchmark::State& state) {
    const glm::vec4 none[1] = {};
    std::vector<SetupTriangle> tris;
    std::vector<Plane> planes;
    for (float y = 0.3f; y + 7 < 64; y += 7)
        for (float x = 0.6f; x + 7 < 64; x += 7) {
            SetupTriangle tri;
            const SetupVertex a{WindowPos{x, y, 0.5f, 1}, none}, b{WindowPos{x + 7, y, 0.5f, 1}, none},
                c{WindowPos{x + 7, y + 7, 0.5f, 1}, none}, d{WindowPos{x, y + 7, 0.5f, 1}, none};
            if (setup_triangle(a, b, c, 0, Interpolations{}, 64, 64, tri, planes)) tris.push_back(tri);
            if (setup_triangle(a, c, d, 0, Interpolations{}, 64, 64, tri, planes)) tris.push_back(tri);
        }
    std::vector<BlockCoverage> blocks;
    long pixels = 0;
    for (auto _ : state) {
        blocks.clear();
        for (const SetupTriangle& tri : tris) rasterize_in_tile(tri, TileRect{0, 0, 64, 64}, blocks);
        benchmark::DoNotOptimize(blocks.data());
        pixels += 64 * 64;
    }
    state.SetItemsProcessed(pixels);
    state.SetLabel("tile pixels");
}
BENCHMARK(BM_RasterizeSmallTriangles);

// Perspective-correct interpolation of 3 varying slots for one whole 4x4
// block (kBlockLanes / kLanes twin inputs).
void BM_InterpolateBlock(benchmark::State& state) {
    std::vector<Plane> planes(2 + 12, Plane{0.5f, 0.01f, 0.02f});
    FragmentLanes lanes;
    LaneGroup groups[2] = {{100, 200, 0, 0xff}, {100, 200, 1, 0xff}};
    for (auto _ : state)
        for (int part = 0; part < kBlockLanes / kLanes; ++part) {
            interpolate_lanes(planes.data(), 3, ~0u, Interpolations{}, groups + part, true, lanes);
            benchmark::DoNotOptimize(lanes);
        }
    state.SetItemsProcessed(int64_t(state.iterations()) * kBlockLanes);
    state.SetLabel("pixels");
}
BENCHMARK(BM_InterpolateBlock);

// Depth-free blending of kLanes lanes into one framebuffer group pair, as
// the output stage does it (load, blend, select, store).
void BM_Blend(benchmark::State& state, BlendMode mode, BlendFactors factors = {}, bool rgba16f = false) {
    alignas(64) float colour[2][4 * kGroupLanes], depth[2][kGroupLanes] = {};
    for (auto& g : colour) std::fill(std::begin(g), std::end(g), 0.5f);
    const Vec4 src(Float(0.1f), Float(0.2f), Float(0.3f), Float(0.4f));
    DrawState ds;
    ds.blend = mode;
    ds.factors = factors;
    const float* in_colour[2] = {colour[0], colour[1]};
    const float* in_depth[2] = {depth[0], depth[1]};
    float* out_colour[2] = {colour[0], colour[1]};
    float* out_depth[2] = {depth[0], depth[1]};
    for (auto _ : state) {
        merge_lanes(ds, rgba16f, src, Float(0.5f), Mask(true), in_colour, in_depth, out_colour, out_depth);
        benchmark::DoNotOptimize(colour);
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * kLanes);
    state.SetLabel("pixels");
}
BENCHMARK_CAPTURE(BM_Blend, none, BlendMode::None);
BENCHMARK_CAPTURE(BM_Blend, one_src_alpha, BlendMode::OneSrcAlpha);
BENCHMARK_CAPTURE(BM_Blend, src_alpha_one_minus_src_alpha, BlendMode::SrcAlphaOneMinusSrcAlpha);
BENCHMARK_CAPTURE(BM_Blend, factors_one_one, BlendMode::Factors, BlendFactors{BlendFactor::One, BlendFactor::One,
                                                                               BlendFactor::One, BlendFactor::One});
BENCHMARK_CAPTURE(BM_Blend, factors_src_colour_one_minus_dst_alpha, BlendMode::Factors,
                  BlendFactors{BlendFactor::SrcColor, BlendFactor::OneMinusDstAlpha, BlendFactor::One,
                               BlendFactor::Zero});
BENCHMARK_CAPTURE(BM_Blend, rgba16f_one_one, BlendMode::Factors,
                  BlendFactors{BlendFactor::One, BlendFactor::One, BlendFactor::One, BlendFactor::One}, true);

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

// texture() on a 256x256 box-filtered mip chain, minified: a 4x4 block
// covers 3 texels per pixel of level 0 (LOD about 1.6, so LINEAR mip
// filters blend levels 1 and 2), every format and min filter.
Texture mip_texture(TextureFormat format, TextureFilter min, MipFilter mip, TextureWrap wrap) {
    Texture t = noise_texture(format == TextureFormat::RGBA8 ? format : TextureFormat::RGBA32F, min);
    t.format = format;
    t.mag_filter = TextureFilter::Linear;
    t.min_filter = min;
    t.mip_filter = mip;
    t.set_wrap(wrap);
    generate_box_mips(t, full_chain_levels(t.width, t.height));
    return t;
}

std::vector<Vec2> minified_uvs(float scale) {
    std::vector<Vec2> uv(4096 / kLanes);
    for (size_t i = 0; i < uv.size(); ++i)
        for (int lane = 0; lane < kLanes; ++lane) {
            const int block = int(i * kLanes / 16) % 4096, bx = block % 64 * 4, by = block / 64 % 64 * 4;
            const int l = int(i * kLanes % 16) + lane;
            uv[i].x.set(lane, (float(bx + block_lane_x(l)) + 0.5f) * scale / 256.0f);
            uv[i].y.set(lane, (float(by + block_lane_y(l)) + 0.5f) * scale / 256.0f);
        }
    return uv;
}

void BM_SampleMip(benchmark::State& state, TextureFormat format, TextureFilter min, MipFilter mip, TextureWrap wrap) {
    const Texture t = mip_texture(format, min, mip, wrap);
    const Sampler2D s(t);
    const std::vector<Vec2> uv = minified_uvs(3.0f);
    for (auto _ : state)
        for (const auto& c : uv) benchmark::DoNotOptimize(s.sample(c));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(uv.size()) * kLanes);
    state.SetLabel("samples");
}
#define ST_MIP_BENCH(fmt, F, min, mip, wrap)                                                                  \
    BENCHMARK_CAPTURE(BM_SampleMip, fmt##_##min##_mip_##mip##_##wrap, TextureFormat::F, TextureFilter::min, \
                      MipFilter::mip, TextureWrap::wrap)
ST_MIP_BENCH(rgba8, RGBA8, Linear, Linear, Repeat);
ST_MIP_BENCH(rgba8, RGBA8, Linear, Nearest, Repeat);
ST_MIP_BENCH(rgba8, RGBA8, Nearest, Linear, Repeat);
ST_MIP_BENCH(rgba8, RGBA8, Nearest, Nearest, Repeat);
ST_MIP_BENCH(rgba8, RGBA8, Linear, Linear, MirroredRepeat);
ST_MIP_BENCH(rgba32f, RGBA32F, Linear, Linear, Repeat);
ST_MIP_BENCH(rgba32f, RGBA32F, Linear, Nearest, Repeat);
ST_MIP_BENCH(rgba32f, RGBA32F, Nearest, Nearest, Repeat);
ST_MIP_BENCH(rgba32f, RGBA32F, Linear, Linear, ClampToEdge);
ST_MIP_BENCH(rgba16f, RGBA16F, Linear, Linear, Repeat);
ST_MIP_BENCH(r32f, R32F, Linear, Linear, Repeat);
#undef ST_MIP_BENCH

// textureLod with a LOD per lane across levels 0..4.
void BM_SampleLod(benchmark::State& state, TextureFormat format) {
    const Texture t = mip_texture(format, TextureFilter::Linear, MipFilter::Linear, TextureWrap::Repeat);
    const Sampler2D s(t);
    const std::vector<Vec2> uv = minified_uvs(1.0f);
    Float lod;
    for (int lane = 0; lane < kLanes; ++lane) lod.set(lane, float(lane % 9) * 0.5f);
    for (auto _ : state)
        for (const auto& c : uv) benchmark::DoNotOptimize(s.sample_lod(c, lod));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(uv.size()) * kLanes);
    state.SetLabel("samples");
}
BENCHMARK_CAPTURE(BM_SampleLod, rgba8_trilinear, TextureFormat::RGBA8);
BENCHMARK_CAPTURE(BM_SampleLod, rgba32f_trilinear, TextureFormat::RGBA32F);

// A seamless cube map (64x64 faces, full chain), trilinear, directions
// sweeping two faces and their edge.
void BM_SampleCube(benchmark::State& state, TextureFormat format) {
    Texture t = noise_texture(format == TextureFormat::RGBA8 ? format : TextureFormat::RGBA32F, TextureFilter::Linear);
    t.format = format;
    t.cube = true;
    t.width = t.height = 64;
    const size_t face = 64 * 64 * 4;
    if (format == TextureFormat::RGBA8) t.texels8.resize(6 * face);
    else t.texels32.resize(6 * face);
    t.mip_filter = MipFilter::Linear;
    generate_box_mips(t, full_chain_levels(64, 64));
    const SamplerCube s(t);
    const std::vector<Vec2> uv = minified_uvs(1.0f);
    for (auto _ : state)
        for (const auto& c : uv) benchmark::DoNotOptimize(s.sample(Vec3(c.x * 2.0f - 1.0f, c.y - 0.5f, Float(0.7f))));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(uv.size()) * kLanes);
    state.SetLabel("samples");
}
BENCHMARK_CAPTURE(BM_SampleCube, rgba8_seamless_trilinear, TextureFormat::RGBA8);
BENCHMARK_CAPTURE(BM_SampleCube, rgba32f_seamless_trilinear, TextureFormat::RGBA32F);

}  // namespace
}  // namespace st
