// binner.h: primitive assembly, clipping (clipper.h), triangle setup
// (triangle_setup.h) and binning into 64x64 tiles, for one pass, in
// parallel (the counterpart of llvmpipe's lp_setup_*; the tiles are then
// rasterized and shaded by tile_shader.h).
//
// The pass's triangles, in draw and index order, are cut into chunks of a
// fixed size, so the cut does not depend on the thread count; each chunk is
// set up on its own and keeps its own bins. A tile reads the chunks' bins in
// chunk order, which is the order its triangles blend in.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "raster/clipper.h"
#include "raster/plane.h"
#include "raster/prepared_draw.h"
#include "raster/triangle_setup.h"

namespace st {

class WorkerPool;

// The set-up triangles of one chunk and the tiles they touch.
struct SetupChunk {
    uint32_t draw = 0;                        // the chunk's triangles are [first, first + count) of this draw
    size_t first = 0, count = 0;
    std::vector<SetupTriangle> triangles;
    std::vector<Plane> planes;                // SetupTriangle::first_plane indexes these
    std::vector<std::vector<uint32_t>> bins;  // [tile] -> indices into `triangles`
    std::deque<ClipVertex> clipped;           // vertices of clipped triangles (stable addresses)
    // Triangles dropped because a window position could not be snapped
    // (triangle_setup.h), and the index in its draw of the first of them.
    size_t unsnappable = 0, first_unsnappable = 0;
};

class Binner {
public:
    // Sets up every triangle of `draws` for a width x height target. The
    // chunks stay valid until the next call.
    void run(std::vector<PreparedDraw>& draws, int width, int height, const Viewport& viewport, WorkerPool& pool);

    int tiles_x() const { return tiles_x_; }
    int tiles() const { return tiles_x_ * tiles_y_; }
    size_t chunk_count() const { return used_; }
    const SetupChunk& chunk(size_t i) const { return chunks_[i]; }
    // The first chunk (in draw order) that dropped a triangle it could not
    // snap, or nullptr: the renderer refuses such a pass.
    const SetupChunk* first_unsnappable() const;
    // Every tile, those with the most binned triangles first (ties by index).
    const std::vector<int>& tiles_by_load() const { return order_; }

private:
    void set_up(SetupChunk& chunk, const PreparedDraw& draw, int width, int height, const Viewport& viewport);

    std::vector<SetupChunk> chunks_;  // grows only; the first used_ are this pass's
    size_t used_ = 0;
    std::vector<int> order_;
    std::vector<size_t> load_;
    int tiles_x_ = 0, tiles_y_ = 0;
};

}  // namespace st
