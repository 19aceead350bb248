// cpu_renderer.cpp: the CPU frame loop (see cpu_renderer.h for the flow).
#include "raster/cpu_renderer.h"

#include <algorithm>
#include <stdexcept>

#include "raster/binner.h"
#include "raster/clipper.h"
#include "raster/float_env.h"
#include "raster/framebuffer.h"
#include "raster/prepared_draw.h"
#include "raster/tile_shader.h"
#include "raster/viewport.h"
#include "raster/worker_pool.h"
#include "shading/twin_library.h"

namespace st {

namespace {

// Vertices per job: small enough that a few thousand spread evenly over the
// workers (a vertex twin that evaluates a model costs about 50 ns a vertex).
constexpr int kVertexChunk = 256;

}  // namespace

struct CpuRenderer::Impl {
    explicit Impl(int threads) : pool(threads), tile_shaders(size_t(threads)) {}

    WorkerPool pool;
    std::vector<TileShader> tile_shaders;  // one per worker
    Frame frame;
    std::vector<std::vector<PreparedDraw>> passes;  // [pass][draw]
    std::unique_ptr<Framebuffer> result;

    Binner binner;  // per-pass setup output, reused across passes and frames

    void run_vertex_stage(PreparedDraw& draw, const Viewport& viewport);
};

CpuRenderer::CpuRenderer(int threads, const TwinLibrary& twins) : twins_(twins) {
    if (threads < 1) throw std::invalid_argument("thread count must be at least 1");
    impl_ = std::make_unique<Impl>(threads);
}

CpuRenderer::~CpuRenderer() = default;

int CpuRenderer::threads() const { return impl_->pool.size(); }

void CpuRenderer::prepare(const Frame& frame) {
    impl_->frame = frame;
    impl_->passes.clear();
    for (const Pass& pass : impl_->frame.passes) {
        auto& draws = impl_->passes.emplace_back();
        for (const DrawCall& call : pass.draws) {
            PreparedDraw& d = draws.emplace_back();
            d.call = &call;
            d.vertices = call.vertices;
            d.vertex = twins_.make_vertex(call.vertex);
            if (!d.vertex) throw std::runtime_error("no C++ twin for vertex program '" + call.vertex + "'");
            d.fragment = twins_.make_fragment(call.fragment);
            if (!d.fragment)
                throw std::runtime_error("no C++ twin for fragment program '" + call.fragment + "'");
            d.bindings.uniforms = &call.uniforms;
            for (const Texture& t : call.textures) {
                if (t.cube) {
                    d.bindings.cube_samplers.push_back(&d.cube_samplers.emplace_back(t));
                    d.bindings.cube_sampler_names.push_back(t.sampler);
                } else {
                    d.bindings.samplers.push_back(&d.samplers.emplace_back(t));
                    d.bindings.sampler_names.push_back(t.sampler);
                }
            }
            d.vertex->bind(d.bindings);
            d.fragment->bind(d.bindings);
            d.varying_count = d.vertex->varying_count();
            d.inputs_read = d.fragment->inputs_read();
        }
    }
}

void CpuRenderer::Impl::run_vertex_stage(PreparedDraw& d, const Viewport& viewport) {
    if (d.call->host_stage) d.call->host_stage->run(d.vertices);
    const VertexArray& va = d.vertices;
    const int n = va.vertex_count();
    d.shaded.resize(size_t(n));
    d.window.resize(size_t(n));
    d.clip_masks.resize(size_t(n));
    pool.run((n + kVertexChunk - 1) / kVertexChunk, [&](int chunk, int) {
        const int end = std::min(n, (chunk + 1) * kVertexChunk);
        for (int v = chunk * kVertexChunk; v < end; ++v) {
            d.vertex->run(va.vertex(v), d.shaded[size_t(v)]);
            d.window[size_t(v)] = to_window(d.shaded[size_t(v)].position, viewport);
            d.clip_masks[size_t(v)] = clip_mask(d.shaded[size_t(v)].position);
        }
    });
}

void CpuRenderer::execute() {
    Impl& m = *impl_;
    const FlushDenormals float_env;  // as llvmpipe's threads (float_env.h)
    times_ = StageTimes{};
    for (size_t pi = 0; pi < m.frame.passes.size(); ++pi) {
        const Pass& pass = m.frame.passes[pi];
        auto& draws = m.passes[pi];
        const Viewport viewport{0, 0, float(pass.width), float(pass.height), 0, 1};
        const auto t0 = Clock::now();
        // The allocation is reused from frame to frame; tiles clear it.
        if (!m.result || m.result->width != pass.width || m.result->height != pass.height)
            m.result = std::make_unique<Framebuffer>(pass.width, pass.height);
        for (PreparedDraw& d : draws) m.run_vertex_stage(d, viewport);
        const auto t1 = Clock::now();
        m.binner.run(draws, pass.width, pass.height, viewport, m.pool);
        const auto t2 = Clock::now();
        for (auto& ts : m.tile_shaders) ts.times = StageTimes{};
        // Busiest tiles first, so that no worker is left with a heavy tile
        // at the end; tiles are independent, so the order changes no pixel.
        const std::vector<int>& order = m.binner.tiles_by_load();
        m.pool.run(int(order.size()), [&](int i, int worker) {
            m.tile_shaders[size_t(worker)].shade(order[size_t(i)], m.binner, draws, pass, *m.result);
        });
        const auto t3 = Clock::now();

        StageTimes tiles;
        for (const auto& ts : m.tile_shaders) tiles += ts.times;
        const double tile_wall = ms_between(t2, t3), tile_cpu = tiles.total_ms();
        const double scale = tile_cpu > 0 ? tile_wall / tile_cpu : 0.0;
        times_.vertex_ms += ms_between(t0, t1);
        times_.setup_ms += ms_between(t1, t2);
        times_.raster_ms += tiles.raster_ms * scale;
        times_.fragment_ms += tiles.fragment_ms * scale;
        times_.output_ms += tiles.output_ms * scale;
    }
}

Image CpuRenderer::read_back() const {
    if (!impl_->result) throw std::runtime_error("CPU: nothing rendered");
    return impl_->result->to_image();
}

}  // namespace st
