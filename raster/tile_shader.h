// tile_shader.h: one 64x64 tile from its bins to pixels: rasterization into
// 8-lane groups (tile_raster.h), the fragment stage (interpolation and the
// twin, kLanes lanes per call) and output merging (output_merge.h), for
// every triangle the binner put there, in order. Each worker owns one
// TileShader and its scratch; a tile is only ever shaded by one worker.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "frame/frame.h"
#include "raster/binner.h"
#include "raster/fragment_inputs.h"
#include "raster/framebuffer.h"
#include "raster/prepared_draw.h"
#include "raster/stage_times.h"
#include "raster/tile_raster.h"

namespace st {

// Aligned to two cache lines (the pair the L2 prefetcher fetches), so that
// the per-worker shaders, side by side in one vector, never share a line.
class alignas(128) TileShader {
public:
    // `fb` is the pass's colour buffer (location 0) and depth; `outputs`
    // its buffers for locations 1, 2, ... (Pass::outputs), often none.
    void shade(int tile, const Binner& binner, const std::vector<PreparedDraw>& draws, const Pass& pass,
               Framebuffer& fb, const std::vector<Framebuffer*>& outputs);

    StageTimes times;  // raster, fragment and output time of the tiles shaded since reset

private:
    // A covered group of a block and the triangle that covers it.
    struct TileGroup {
        LaneGroup group;
        const SetupTriangle* triangle = nullptr;
        const Plane* planes = nullptr;  // its z, 1/w and varying planes
    };
    // One twin call after the fragment stage: what output merging needs.
    struct ShadedCall {
        FragmentResult result;
        Float depth;          // gl_FragCoord.z, clamped
        unsigned live = 0;    // covered and not discarded, bit i = lane i
        uint32_t first = 0;   // its groups: groups_[first ...]
    };

    void rasterize(const SetupTriangle& tri, const Plane* planes, const TileRect& rect);
    size_t shade_groups(const std::vector<PreparedDraw>& draws);
    void merge(size_t calls, const std::vector<PreparedDraw>& draws, const TileRect& rect, Framebuffer& fb);
    void clear_unwritten(const TileRect& rect, Framebuffer& fb) const;

    // The clear is lazy: a group the tile has not written yet reads its
    // destination from these (the pass's clear values), and groups still
    // unwritten at the end of the tile get them stored.
    static constexpr int kTileGroups = 2 * (kTileSize / kBlockSize) * (kTileSize / kBlockSize);
    static int tile_group(const LaneGroup& g, const TileRect& rect) {
        return (((g.y - rect.y0) / kBlockSize) * (kTileSize / kBlockSize) + (g.x - rect.x0) / kBlockSize) * 2 + g.half;
    }
    bool written_[kTileGroups] = {};
    float clear_colour_[4 * kGroupLanes] = {}, clear_depth_[kGroupLanes] = {};
    bool depth_used_ = false;  // some draw of the pass tests depth
    bool rgba16f_ = false;     // the colour buffer stores halves

    // The pass's colour buffers at locations 1, 2, ..., each with its own
    // format and clear value, and per shaded call the twin's values for
    // them (apart from ShadedCall, so that a pass with one target keeps its
    // shaded results as small as they were).
    struct Output {
        Framebuffer* fb = nullptr;
        bool rgba16f = false;
        float clear_colour[4 * kGroupLanes] = {};
    };
    std::vector<Output> outputs_;
    std::vector<std::array<Vec4, kMaxFragmentOutputs - 1>> output_values_;  // grows only

    std::vector<BlockCoverage> blocks_;
    std::vector<TileGroup> groups_;
    FragmentLanes inputs_;
    std::vector<ShadedCall> shaded_;  // grows only
    float spare_colour_[4 * kGroupLanes] = {}, spare_depth_[kGroupLanes] = {};
};

}  // namespace st
