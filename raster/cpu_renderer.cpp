// cpu_renderer.cpp: the CPU frame loop (see cpu_renderer.h for the flow).
#include "raster/cpu_renderer.h"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include "raster/clipper.h"
#include "raster/float_env.h"
#include "raster/fragment_inputs.h"
#include "raster/framebuffer.h"
#include "raster/output_merge.h"
#include "texture/sampler2d.h"
#include "raster/tile_raster.h"
#include "raster/triangle_setup.h"
#include "raster/viewport.h"
#include "raster/worker_pool.h"
#include "shading/twin_library.h"

namespace st {

namespace {

constexpr int kVertexChunk = 1024;

struct PreparedDraw {
    const DrawCall* call = nullptr;
    VertexArray vertices;                 // this frame's vertices (the host stage writes here)
    std::unique_ptr<VertexTwin> vertex;
    std::unique_ptr<FragmentTwin> fragment;
    std::deque<Sampler2D> samplers;  // deque: Bindings keeps pointers
    Bindings bindings;
    int varying_count = 0;
    std::vector<VertexOut> shaded;        // vertex stage output, per vertex
    std::vector<WindowPos> window;        // viewport transform of `shaded`
    std::vector<unsigned> clip_masks;     // outcodes of `shaded`
};

// One twin call after the fragment stage: what output merging needs.
struct ShadedCall {
    FragmentResult result;
    Float depth;          // gl_FragCoord.z, clamped
    unsigned live = 0;    // covered and not discarded, bit i = lane i
    uint32_t first = 0;   // its groups: WorkerScratch::groups[first ...]
};

// A covered group of a block and the triangle (index into the pass's
// triangles) that covers it.
struct TileGroup {
    LaneGroup group;
    uint32_t triangle = 0;
};

constexpr int kGroupsPerCall = kLanes / kGroupLanes;
// Groups rasterized, shaded and merged at a time in one tile: bounds the
// scratch memory whatever the overdraw.
constexpr size_t kMaxTileGroups = 4096;

// Per-worker scratch, so the tile phase allocates nothing once warm.
struct WorkerScratch {
    std::vector<BlockCoverage> blocks;
    std::vector<TileGroup> groups;
    FragmentLanes inputs;
    std::vector<ShadedCall> shaded;
    float spare_colour[4 * kGroupLanes] = {}, spare_depth[kGroupLanes] = {};
    StageTimes times;
};

}  // namespace

struct CpuRenderer::Impl {
    explicit Impl(int threads) : pool(threads), scratch(size_t(threads)) {}

    WorkerPool pool;
    std::vector<WorkerScratch> scratch;
    Frame frame;
    std::vector<std::vector<PreparedDraw>> passes;  // [pass][draw]
    std::unique_ptr<Framebuffer> result;

    // Per-pass setup output, reused across passes and frames.
    std::vector<SetupTriangle> triangles;
    std::vector<Plane> planes;
    std::vector<std::vector<uint32_t>> bins;
    std::deque<ClipVertex> clipped;  // vertices of clipped triangles (stable addresses)

    void run_vertex_stage(PreparedDraw& draw, const Viewport& viewport);
    void setup_and_bin(std::vector<PreparedDraw>& draws, const Pass& pass, const Viewport& viewport);
    void shade_tile(int tile, int worker, std::vector<PreparedDraw>& draws, const Pass& pass,
                    Framebuffer& fb);
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
                d.bindings.samplers.push_back(&d.samplers.emplace_back(t));
                d.bindings.sampler_names.push_back(t.sampler);
            }
            d.vertex->bind(d.bindings);
            d.fragment->bind(d.bindings);
            d.varying_count = d.vertex->varying_count();
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

// Primitive assembly, clipping (clipper.h), setup (triangle_setup.h) and
// binning, in draw and index order: the order of each tile's bin is the
// order in which its triangles blend.
void CpuRenderer::Impl::setup_and_bin(std::vector<PreparedDraw>& draws, const Pass& pass,
                                      const Viewport& viewport) {
    triangles.clear();
    planes.clear();
    clipped.clear();
    const int tiles_x = (pass.width + kTileSize - 1) / kTileSize;
    const int tiles_y = (pass.height + kTileSize - 1) / kTileSize;
    bins.resize(size_t(tiles_x) * tiles_y);
    for (auto& bin : bins) bin.clear();

    auto emit = [&](const SetupVertex& a, const SetupVertex& b, const SetupVertex& c, uint32_t draw,
                    int varying_count) {
        SetupTriangle tri;
        if (!setup_triangle(a, b, c, varying_count, pass.width, pass.height, tri, planes)) return;
        tri.draw = draw;
        const auto index = uint32_t(triangles.size());
        triangles.push_back(tri);
        for (int ty = tri.y_min / kTileSize; ty <= tri.y_max / kTileSize; ++ty)
            for (int tx = tri.x_min / kTileSize; tx <= tri.x_max / kTileSize; ++tx)
                bins[size_t(ty) * tiles_x + tx].push_back(index);
    };

    std::vector<ClipVertex> clipped_tris;
    for (uint32_t di = 0; di < draws.size(); ++di) {
        PreparedDraw& d = draws[di];
        const auto& idx = d.call->indices;
        for (size_t t = 0; t + 2 < idx.size(); t += 3) {
            const uint32_t i[3] = {idx[t], idx[t + 1], idx[t + 2]};
            unsigned mask_or = 0, mask_and = ~0u;
            for (uint32_t k : i) {
                mask_or |= d.clip_masks[k];
                mask_and &= d.clip_masks[k];
            }
            if (mask_and) continue;  // entirely outside one plane
            if (!mask_or) {
                SetupVertex sv[3];
                for (int k = 0; k < 3; ++k) sv[k] = {d.window[i[k]], d.shaded[i[k]].varyings.data()};
                emit(sv[0], sv[1], sv[2], di, d.varying_count);
                continue;
            }
            ClipVertex cv[3];
            for (int k = 0; k < 3; ++k) cv[k] = {d.shaded[i[k]], d.window[i[k]]};
            clipped_tris.clear();
            clip_triangle(cv[0], cv[1], cv[2], mask_or, d.varying_count, viewport, clipped_tris);
            for (size_t k = 0; k + 2 < clipped_tris.size(); k += 3) {
                SetupVertex sv[3];
                for (int j = 0; j < 3; ++j) {
                    const ClipVertex& kept = clipped.emplace_back(clipped_tris[k + size_t(j)]);
                    sv[j] = {kept.window, kept.out.varyings.data()};
                }
                emit(sv[0], sv[1], sv[2], di, d.varying_count);
            }
        }
    }
}

// A tile in three phases, so that each is timed once per batch rather than
// once per triangle: rasterize a batch of triangles into 8-lane groups,
// shade the groups (kGroupsPerCall of the same triangle per twin call),
// then depth-test and blend them in triangle order. Twins never read the
// framebuffer, so shading ahead of merging changes nothing.
void CpuRenderer::Impl::shade_tile(int tile, int worker, std::vector<PreparedDraw>& draws,
                                   const Pass& pass, Framebuffer& fb) {
    WorkerScratch& s = scratch[size_t(worker)];
    const int tiles_x = (pass.width + kTileSize - 1) / kTileSize;
    const TileRect rect{(tile % tiles_x) * kTileSize, (tile / tiles_x) * kTileSize,
                        std::min(pass.width, (tile % tiles_x + 1) * kTileSize),
                        std::min(pass.height, (tile / tiles_x + 1) * kTileSize)};
    // The clear is part of the frame, as glClear is on the GL side; each
    // tile clears its own blocks, in parallel and while they are in cache.
    fb.clear(rect.x0, rect.y0, rect.x1, rect.y1, pass.clear_colour, pass.clear_depth);
    const std::vector<uint32_t>& bin = bins[size_t(tile)];
    for (size_t next = 0; next < bin.size();) {
        const auto t0 = Clock::now();
        s.groups.clear();
        for (; next < bin.size() && s.groups.size() < kMaxTileGroups; ++next) {
            s.blocks.clear();
            rasterize_in_tile(triangles[bin[next]], rect, s.blocks);
            for (const BlockCoverage& block : s.blocks)
                for (int half = 0; half < 2; ++half)
                    if (const unsigned mask = block.mask >> (half * kGroupLanes) & 0xff)
                        s.groups.push_back({LaneGroup{block.x, block.y, half, mask}, bin[next]});
        }
        const auto t1 = Clock::now();

        // Fragment stage. Groups without a covered lane never got here
        // (llvmpipe skips such vectors too); a call short of groups fills up
        // with an uncovered copy of its last one, whose results are dropped.
        size_t shaded = 0;
        for (size_t i = 0; i < s.groups.size();) {
            const uint32_t tri_index = s.groups[i].triangle;
            const SetupTriangle& tri = triangles[tri_index];
            const PreparedDraw& d = draws[tri.draw];
            LaneGroup call[kGroupsPerCall];
            const auto first = uint32_t(i);
            int n = 0;
            for (; n < kGroupsPerCall && i < s.groups.size() && s.groups[i].triangle == tri_index; ++n, ++i)
                call[n] = s.groups[i].group;
            for (int g = n; g < kGroupsPerCall; ++g) call[g] = LaneGroup{call[n - 1].x, call[n - 1].y, call[n - 1].half, 0};
            interpolate_lanes(&planes[tri.first_plane], d.varying_count, call, tri.front_facing, s.inputs);
            // Grow only: a new ShadedCall is 400 zeroed bytes, and the twin
            // writes every field that is read.
            if (shaded == s.shaded.size()) s.shaded.emplace_back();
            ShadedCall& out = s.shaded[shaded];
            d.fragment->shade(s.inputs, out.result);
            out.live = simd::bits(and_not(s.inputs.covered, out.result.discarded));
            out.depth = s.inputs.frag_coord.z;
            out.first = first;
            if (out.live) ++shaded;
        }
        const auto t2 = Clock::now();

        for (size_t k = 0; k < shaded; ++k) {
            const ShadedCall& call = s.shaded[k];
            const DrawState& state = draws[triangles[s.groups[call.first].triangle].draw].call->state;
            float* colour[kGroupsPerCall];
            float* depth[kGroupsPerCall];
            for (int g = 0; g < kGroupsPerCall; ++g) {
                // A group without a live lane (padding, or all discarded)
                // loads and stores a scratch copy, never the framebuffer.
                if (!(call.live >> (g * kGroupLanes) & 0xff)) {
                    colour[g] = s.spare_colour;
                    depth[g] = s.spare_depth;
                    continue;
                }
                const TileGroup& tg = s.groups[call.first + uint32_t(g)];
                const size_t b = fb.block(tg.group.x, tg.group.y);
                colour[g] = fb.group_colour(b, tg.group.half);
                depth[g] = fb.group_depth(b, tg.group.half);
            }
            merge_lanes(state, call.result.colour, call.depth, Mask::from_bits(call.live), colour, depth);
        }
        const auto t3 = Clock::now();
        s.times.raster_ms += ms_between(t0, t1);
        s.times.fragment_ms += ms_between(t1, t2);
        s.times.output_ms += ms_between(t2, t3);
    }
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
        m.setup_and_bin(draws, pass, viewport);
        const auto t2 = Clock::now();
        for (auto& s : m.scratch) s.times = StageTimes{};
        m.pool.run(int(m.bins.size()),
                   [&](int tile, int worker) { m.shade_tile(tile, worker, draws, pass, *m.result); });
        const auto t3 = Clock::now();

        StageTimes tiles;
        for (const auto& s : m.scratch) tiles += s.times;
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
