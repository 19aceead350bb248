// cpu_renderer.cpp: the CPU frame loop (see cpu_renderer.h for the flow).
#include "raster/cpu_renderer.h"

#include <algorithm>
#include <map>
#include <string>
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
    std::unique_ptr<Framebuffer> result;   // the frame's image
    std::unique_ptr<Framebuffer> target_fb;  // a named target's level while a pass draws into it
    std::vector<std::unique_ptr<Framebuffer>> output_fbs;  // Pass::outputs' levels while a pass draws into them
    // Named targets as the passes so far left them: per level, RGBA texels
    // with row 0 at the bottom (halves already rounded for RGBA16F).
    std::map<std::string, std::vector<std::vector<float>>> targets;
    const RenderTarget* target(const std::string& name) const {
        for (const RenderTarget& t : frame.targets)
            if (t.name == name) return &t;
        return nullptr;
    }
    void refresh_target_textures(std::vector<PreparedDraw>& draws);

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
    impl_->targets.clear();  // execute() allocates them for this frame's targets
    for (const Pass& pass : impl_->frame.passes) {
        if (pass.outputs.size() > size_t(kMaxFragmentOutputs - 1))
            throw std::runtime_error("a pass draws into at most " + std::to_string(kMaxFragmentOutputs) + " targets");
        for (const PassOutput& o : pass.outputs) {
            const RenderTarget* rt = impl_->target(o.target);
            if (!rt || o.level < 0 || o.level >= rt->levels || std::max(1, rt->width >> o.level) != pass.width ||
                std::max(1, rt->height >> o.level) != pass.height || rt->format != o.format)
                throw std::runtime_error("a pass output names target '" + o.target + "' level " +
                                         std::to_string(o.level) + ", which is not a level of the pass's size and format");
        }
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
                if (!t.target.empty()) {
                    // Sized and filtered as the target; texels each frame.
                    const RenderTarget* rt = impl_->target(t.target);
                    if (!rt) throw std::runtime_error("texture '" + t.sampler + "' reads unknown target " + t.target);
                    auto& tt = d.target_textures.emplace_back();
                    tt.texture = t;
                    tt.texture.format = TextureFormat::RGBA32F;  // the stored values, halves included, as floats
                    tt.texture.width = rt->width;
                    tt.texture.height = rt->height;
                    tt.texture.texels32.assign(size_t(rt->width) * size_t(rt->height) * 4, 0.0f);
                    for (int level = 1; level < rt->levels; ++level) {
                        TextureLevel l;
                        l.width = std::max(1, rt->width >> level);
                        l.height = std::max(1, rt->height >> level);
                        l.texels32.assign(size_t(l.width) * size_t(l.height) * 4, 0.0f);
                        tt.texture.mips.push_back(std::move(l));
                    }
                    tt.sampler = &d.samplers.emplace_back(tt.texture);
                    d.bindings.samplers.push_back(tt.sampler);
                    d.bindings.sampler_names.push_back(t.sampler);
                } else if (t.cube) {
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
            d.interpolation = d.fragment->interpolations();
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

// Copies the current texels of each render target a draw samples into its
// texture and its sampler (same size and levels, so the twin's binding
// stays valid; nothing is allocated).
void CpuRenderer::Impl::refresh_target_textures(std::vector<PreparedDraw>& draws) {
    // Straight from the target into the sampler's arrays (the texture's own
    // texel arrays are not read once it is bound), a texture a job.
    std::vector<PreparedDraw::TargetTexture*> all;
    for (PreparedDraw& d : draws)
        for (auto& tt : d.target_textures) all.push_back(&tt);
    pool.run(int(all.size()), [&](int i, int) {
        PreparedDraw::TargetTexture& tt = *all[size_t(i)];
        tt.sampler->reload_texels(targets.at(tt.texture.target));
    });
}

void CpuRenderer::execute() {
    Impl& m = *impl_;
    const FlushDenormals float_env;  // as llvmpipe's threads (float_env.h)
    const WorkerPool::Frame awake(m.pool);
    times_ = StageTimes{};
    // Every target starts the frame at zero, as on the GL side (the last
    // frame's allocations are kept; prepare() drops them with the frame).
    if (m.targets.empty()) {
        for (const RenderTarget& t : m.frame.targets)
            for (int level = 0; level < t.levels; ++level)
                m.targets[t.name].emplace_back(
                    size_t(std::max(1, t.width >> level)) * size_t(std::max(1, t.height >> level)) * 4, 0.0f);
    } else {
        std::vector<std::vector<float>*> all;
        for (auto& [name, levels] : m.targets)
            for (std::vector<float>& level : levels) all.push_back(&level);
        m.pool.run(int(all.size()), [&](int i, int) { std::fill(all[size_t(i)]->begin(), all[size_t(i)]->end(), 0.0f); });
    }
    bool frame_started = false;  // a frame pass has drawn into m.result this frame
    for (size_t pi = 0; pi < m.frame.passes.size(); ++pi) {
        const Pass& pass = m.frame.passes[pi];
        auto& draws = m.passes[pi];
        const Viewport viewport{float(pass.viewport_x), float(pass.viewport_y),
                                float(pass.viewport_width ? pass.viewport_width : pass.width),
                                float(pass.viewport_height ? pass.viewport_height : pass.height), 0, 1};
        const auto t0 = Clock::now();
        m.refresh_target_textures(draws);
        // The allocations are reused from frame to frame; tiles clear them.
        std::unique_ptr<Framebuffer>& fb = pass.target.empty() ? m.result : m.target_fb;
        const bool resized = !fb || fb->width != pass.width || fb->height != pass.height;
        if (resized) fb = std::make_unique<Framebuffer>(pass.width, pass.height);
        if (!pass.target.empty() && !pass.clear) fb->load_texels(m.targets.at(pass.target)[size_t(pass.level)]);
        // The frame image starts each frame at zero, as on the GL side: a
        // first frame pass that does not clear must not draw over the last
        // frame's image, which the reused allocation still holds.
        if (pass.target.empty() && !pass.clear && (resized || !frame_started))
            fb->load_texels(std::vector<float>(size_t(pass.width) * size_t(pass.height) * 4, 0.0f));
        if (pass.target.empty()) frame_started = true;
        // Locations 1, 2, ...: their targets' levels, kept or cleared as the pass's.
        std::vector<Framebuffer*> outputs;
        m.output_fbs.resize(std::max(m.output_fbs.size(), pass.outputs.size()));
        for (size_t k = 0; k < pass.outputs.size(); ++k) {
            std::unique_ptr<Framebuffer>& o = m.output_fbs[k];
            if (!o || o->width != pass.width || o->height != pass.height)
                o = std::make_unique<Framebuffer>(pass.width, pass.height);
            if (!pass.clear) o->load_texels(m.targets.at(pass.outputs[k].target)[size_t(pass.outputs[k].level)]);
            outputs.push_back(o.get());
        }
        for (PreparedDraw& d : draws) m.run_vertex_stage(d, viewport);
        const auto t1 = Clock::now();
        m.binner.run(draws, pass.width, pass.height, viewport, m.pool);
        if (const SetupChunk* bad = m.binner.first_unsnappable())
            throw UnrenderableInput(
                "pass " + std::to_string(pi) + ", draw " + std::to_string(bad->draw) + ", triangle " +
                std::to_string(bad->first_unsnappable) +
                ": a vertex's window position is not finite (clip w at or within a few ULP of 0, or a vertex at "
                "the clip-space origin), so it cannot be rasterized as llvmpipe would; move it off w = 0");
        const auto t2 = Clock::now();
        for (auto& ts : m.tile_shaders) ts.times = StageTimes{};
        // Busiest tiles first, so that no worker is left with a heavy tile
        // at the end; tiles are independent, so the order changes no pixel.
        const std::vector<int>& order = m.binner.tiles_by_load();
        m.pool.run(int(order.size()), [&](int i, int worker) {
            m.tile_shaders[size_t(worker)].shade(order[size_t(i)], m.binner, draws, pass, *fb, outputs);
        });
        // The targets' texels for later passes, a block row a job (they
        // are the size the frame allocated for them).
        auto keep = [&](const Framebuffer& from, std::vector<float>& to) {
            m.pool.run(from.blocks_y, [&](int row, int) { from.texels_of_block_row(row, to.data()); });
        };
        if (!pass.target.empty()) keep(*fb, m.targets.at(pass.target)[size_t(pass.level)]);
        for (size_t k = 0; k < pass.outputs.size(); ++k)
            keep(*outputs[k], m.targets.at(pass.outputs[k].target)[size_t(pass.outputs[k].level)]);
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

Image CpuRenderer::read_back(const std::string& target, int level) const {
    const auto it = impl_->targets.find(target);
    const RenderTarget* rt = impl_->target(target);
    if (it == impl_->targets.end() || !rt || level < 0 || level >= int(it->second.size()))
        throw std::runtime_error("CPU: no render target " + target + " level " + std::to_string(level));
    const int w = std::max(1, rt->width >> level), h = std::max(1, rt->height >> level);
    const std::vector<float>& texels = it->second[size_t(level)];
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        std::copy_n(&texels[size_t(h - 1 - y) * size_t(w) * 4], size_t(w) * 4, image.pixel(0, y));
    return image;
}

}  // namespace st
