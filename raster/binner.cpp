// binner.cpp: see binner.h.
#include "raster/binner.h"

#include <algorithm>

#include "raster/tile_raster.h"
#include "raster/worker_pool.h"

namespace st {

namespace {
// Triangles per chunk: enough to keep a worker busy for a while, few enough
// that a scene of a few thousand triangles still spreads over the workers.
constexpr size_t kChunkTriangles = 256;
}  // namespace

void Binner::run(std::vector<PreparedDraw>& draws, int width, int height, const Viewport& viewport,
                 WorkerPool& pool) {
    tiles_x_ = (width + kTileSize - 1) / kTileSize;
    tiles_y_ = (height + kTileSize - 1) / kTileSize;
    used_ = 0;
    for (uint32_t di = 0; di < draws.size(); ++di) {
        const size_t triangles = draws[di].call->indices.size() / 3;
        for (size_t first = 0; first < triangles; first += kChunkTriangles) {
            if (used_ == chunks_.size()) chunks_.emplace_back();
            SetupChunk& c = chunks_[used_++];
            c.draw = di;
            c.first = first;
            c.count = std::min(kChunkTriangles, triangles - first);
        }
    }
    pool.run(int(used_), [&](int i, int) {
        SetupChunk& c = chunks_[size_t(i)];
        set_up(c, draws[c.draw], width, height, viewport);
    });
    load_.assign(size_t(tiles()), 0);
    for (size_t i = 0; i < used_; ++i)
        for (size_t t = 0; t < load_.size(); ++t) load_[t] += chunks_[i].bins[t].size();
    order_.resize(size_t(tiles()));
    for (int t = 0; t < tiles(); ++t) order_[size_t(t)] = t;
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) { return load_[size_t(a)] > load_[size_t(b)]; });
}

const SetupChunk* Binner::first_unsnappable() const {
    for (size_t i = 0; i < used_; ++i)
        if (chunks_[i].unsnappable) return &chunks_[i];
    return nullptr;
}

void Binner::set_up(SetupChunk& chunk, const PreparedDraw& d, int width, int height, const Viewport& viewport) {
    chunk.triangles.clear();
    chunk.planes.clear();
    chunk.clipped.clear();
    chunk.unsnappable = 0;
    chunk.bins.resize(size_t(tiles()));
    for (auto& bin : chunk.bins) bin.clear();

    size_t triangle = 0;  // index in the draw of the triangle being set up
    auto emit = [&](const SetupVertex& a, const SetupVertex& b, const SetupVertex& c) {
        if (!snappable(a, b, c)) {
            if (chunk.unsnappable++ == 0) chunk.first_unsnappable = triangle;
            return;
        }
        SetupTriangle tri;
        if (!setup_triangle(a, b, c, d.varying_count, d.interpolation, width, height, tri, chunk.planes)) return;
        tri.draw = chunk.draw;
        const auto index = uint32_t(chunk.triangles.size());
        chunk.triangles.push_back(tri);
        for (int ty = tri.y_min / kTileSize; ty <= tri.y_max / kTileSize; ++ty)
            for (int tx = tri.x_min / kTileSize; tx <= tri.x_max / kTileSize; ++tx)
                chunk.bins[size_t(ty) * tiles_x_ + tx].push_back(index);
    };

    std::vector<ClipVertex> clipped_tris;
    const auto& idx = d.call->indices;
    for (size_t t = chunk.first * 3; t < (chunk.first + chunk.count) * 3; t += 3) {
        triangle = t / 3;
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
            emit(sv[0], sv[1], sv[2]);
            continue;
        }
        ClipVertex cv[3];
        for (int k = 0; k < 3; ++k) cv[k] = {d.shaded[i[k]], d.window[i[k]]};
        clipped_tris.clear();
        clip_triangle(cv[0], cv[1], cv[2], mask_or, d.varying_count, d.interpolation, viewport, clipped_tris);
        for (size_t k = 0; k + 2 < clipped_tris.size(); k += 3) {
            SetupVertex sv[3];
            for (int j = 0; j < 3; ++j) {
                const ClipVertex& kept = chunk.clipped.emplace_back(clipped_tris[k + size_t(j)]);
                sv[j] = {kept.window, kept.out.varyings.data()};
            }
            emit(sv[0], sv[1], sv[2]);
        }
    }
}

}  // namespace st
