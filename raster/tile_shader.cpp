// tile_shader.cpp: see tile_shader.h.
//
// A tile runs in three phases, so that each is timed once per batch rather
// than once per triangle: rasterize a batch of triangles into 8-lane groups,
// shade the groups (kGroupsPerCall of the same triangle per twin call), then
// depth-test and blend them in triangle order. Twins never read the
// framebuffer, so shading ahead of merging changes nothing.
#include "raster/tile_shader.h"

#include <algorithm>

#include "raster/output_merge.h"
#include "texture/texel_formats.h"

namespace st {

namespace {

constexpr int kGroupsPerCall = kLanes / kGroupLanes;
// Groups rasterized, shaded and merged at a time in one tile: bounds the
// scratch memory whatever the overdraw, and keeps the shaded results (about
// 230 bytes a group) in the L2 cache until they are merged.
constexpr size_t kMaxTileGroups = 512;

}  // namespace

void TileShader::shade(int tile, const Binner& binner, const std::vector<PreparedDraw>& draws, const Pass& pass,
                       Framebuffer& fb, const std::vector<Framebuffer*>& outputs) {
    const int tiles_x = binner.tiles_x();
    const TileRect rect{(tile % tiles_x) * kTileSize, (tile / tiles_x) * kTileSize,
                        std::min(pass.width, (tile % tiles_x + 1) * kTileSize),
                        std::min(pass.height, (tile / tiles_x + 1) * kTileSize)};
    // The clear is part of the frame, as glClear is on the GL side; each
    // tile clears its own blocks, lazily (tile_shader.h).
    rgba16f_ = pass.format == TargetFormat::RGBA16F;
    // An RGBA16F clear is rounded as any store to it.
    for (int c = 0; c < 4; ++c)
        std::fill_n(clear_colour_ + c * kGroupLanes, kGroupLanes,
                    rgba16f_ ? rgba16f_stored(pass.clear_colour[c]) : pass.clear_colour[c]);
    std::fill_n(clear_depth_, kGroupLanes, pass.clear_depth);
    // glClear clears every draw buffer to the one colour, each rounded as
    // its format stores it.
    outputs_.resize(outputs.size());
    for (size_t k = 0; k < outputs.size(); ++k) {
        Output& o = outputs_[k];
        o.fb = outputs[k];
        o.rgba16f = k < pass.outputs.size() && pass.outputs[k].format == TargetFormat::RGBA16F;
        for (int c = 0; c < 4; ++c)
            std::fill_n(o.clear_colour + c * kGroupLanes, kGroupLanes,
                        o.rgba16f ? rgba16f_stored(pass.clear_colour[c]) : pass.clear_colour[c]);
    }
    // Depth is only ever read by a depth test: in a pass without one it is
    // neither cleared nor written (read_back() returns colour only).
    depth_used_ = std::any_of(draws.begin(), draws.end(), [](const PreparedDraw& d) { return d.call->state.depth_test; });
    // A pass that does not clear draws over what the framebuffer holds
    // (the caller has loaded it); it tests no depth (scenes check).
    std::fill_n(written_, kTileGroups, !pass.clear);
    size_t chunk = 0, next = 0;  // the next triangle: chunk's bin entry `next`
    while (chunk < binner.chunk_count()) {
        const auto t0 = Clock::now();
        groups_.clear();
        for (; chunk < binner.chunk_count() && groups_.size() < kMaxTileGroups; ++chunk, next = 0) {
            const SetupChunk& c = binner.chunk(chunk);
            const std::vector<uint32_t>& bin = c.bins[size_t(tile)];
            for (; next < bin.size() && groups_.size() < kMaxTileGroups; ++next)
                rasterize(c.triangles[bin[next]], &c.planes[c.triangles[bin[next]].first_plane], rect);
            if (next < bin.size()) break;  // the batch is full: go on from here
        }
        const auto t1 = Clock::now();
        const size_t calls = shade_groups(draws);
        const auto t2 = Clock::now();
        merge(calls, draws, rect, fb);
        const auto t3 = Clock::now();
        times.raster_ms += ms_between(t0, t1);
        times.fragment_ms += ms_between(t1, t2);
        times.output_ms += ms_between(t2, t3);
    }
    const auto t0 = Clock::now();
    clear_unwritten(rect, fb);
    times.output_ms += ms_between(t0, Clock::now());
}

void TileShader::clear_unwritten(const TileRect& rect, Framebuffer& fb) const {
    for (int y = rect.y0; y < rect.y1; y += kBlockSize)
        for (int x = rect.x0; x < rect.x1; x += kBlockSize)
            for (int half = 0; half < 2; ++half) {
                if (written_[tile_group(LaneGroup{x, y, half, 0}, rect)]) continue;
                const size_t b = fb.block(x, y);
                std::copy_n(clear_colour_, 4 * kGroupLanes, fb.group_colour(b, half));
                if (depth_used_) std::copy_n(clear_depth_, kGroupLanes, fb.group_depth(b, half));
                for (const Output& o : outputs_) std::copy_n(o.clear_colour, 4 * kGroupLanes, o.fb->group_colour(b, half));
            }
}

void TileShader::rasterize(const SetupTriangle& tri, const Plane* planes, const TileRect& rect) {
    blocks_.clear();
    rasterize_in_tile(tri, rect, blocks_);
    for (const BlockCoverage& block : blocks_)
        for (int half = 0; half < 2; ++half)
            if (const unsigned mask = block.mask >> (half * kGroupLanes) & 0xff)
                groups_.push_back({LaneGroup{block.x, block.y, half, mask}, &tri, planes});
}

// Groups without a covered lane never get here (llvmpipe skips such vectors
// too); a call short of groups fills up with an uncovered copy of its last
// one, whose results are dropped. Returns the number of calls with a live
// lane, in shaded_.
size_t TileShader::shade_groups(const std::vector<PreparedDraw>& draws) {
    size_t shaded = 0;
    for (size_t i = 0; i < groups_.size();) {
        const SetupTriangle* tri = groups_[i].triangle;
        const PreparedDraw& d = draws[tri->draw];
        LaneGroup call[kGroupsPerCall];
        const auto first = uint32_t(i);
        int n = 0;
        for (; n < kGroupsPerCall && i < groups_.size() && groups_[i].triangle == tri; ++n, ++i)
            call[n] = groups_[i].group;
        for (int g = n; g < kGroupsPerCall; ++g) call[g] = LaneGroup{call[n - 1].x, call[n - 1].y, call[n - 1].half, 0};
        interpolate_lanes(groups_[first].planes, d.varying_count, d.inputs_read, d.interpolation, call, tri->front_facing, inputs_);
        // Grow only: a new ShadedCall is 400 zeroed bytes, and the twin
        // writes every field that is read.
        if (shaded == shaded_.size()) shaded_.emplace_back();
        ShadedCall& out = shaded_[shaded];
        if (!outputs_.empty()) {
            if (shaded == output_values_.size()) output_values_.emplace_back();
            out.result.outputs = output_values_[shaded].data();
        }
        d.fragment->shade(inputs_, out.result);
        out.live = simd::bits(and_not(inputs_.covered, out.result.discarded));
        out.depth = inputs_.frag_coord.z;
        out.first = first;
        if (out.live) ++shaded;
    }
    return shaded;
}

void TileShader::merge(size_t calls, const std::vector<PreparedDraw>& draws, const TileRect& rect,
                       Framebuffer& fb) {
    for (size_t k = 0; k < calls; ++k) {
        const ShadedCall& call = shaded_[k];
        const DrawState& state = draws[groups_[call.first].triangle->draw].call->state;
        const bool stores_depth = state.depth_test && state.depth_write;
        const float* in_colour[kGroupsPerCall];
        const float* in_depth[kGroupsPerCall];
        float* out_colour[kGroupsPerCall];
        float* out_depth[kGroupsPerCall];
        // Where each group sits, for the other colour buffers (none: a scratch copy).
        const bool has_outputs = !outputs_.empty();
        size_t block[kGroupsPerCall] = {};
        int half[kGroupsPerCall] = {};
        bool fresh[kGroupsPerCall] = {};  // not written before this call: reads the clear value
        for (int g = 0; g < kGroupsPerCall; ++g) {
            // A group without a live lane (padding, or all discarded) loads
            // and stores a scratch copy, never the framebuffer.
            if (!(call.live >> (g * kGroupLanes) & 0xff)) {
                in_colour[g] = out_colour[g] = spare_colour_;
                in_depth[g] = out_depth[g] = spare_depth_;
                half[g] = -1;
                continue;
            }
            const LaneGroup& group = groups_[call.first + uint32_t(g)].group;
            const size_t b = fb.block(group.x, group.y);
            out_colour[g] = fb.group_colour(b, group.half);
            out_depth[g] = fb.group_depth(b, group.half);
            bool& written = written_[tile_group(group, rect)];
            if (has_outputs) block[g] = b, half[g] = group.half, fresh[g] = !written;
            if (written) {
                in_colour[g] = out_colour[g];
                in_depth[g] = out_depth[g];
            } else {
                in_colour[g] = clear_colour_;
                in_depth[g] = clear_depth_;
                if (!stores_depth && depth_used_) std::copy_n(clear_depth_, kGroupLanes, out_depth[g]);
                written = true;
            }
        }
        if (!has_outputs) {  // one colour buffer: the whole merge in one inlined step
            merge_lanes(state, rgba16f_, call.result.colour, call.depth, Mask::from_bits(call.live), in_colour,
                        in_depth, out_colour, out_depth);
            continue;
        }
        const Mask pass = depth_tested(state, call.depth, Mask::from_bits(call.live), in_depth, out_depth);
        merge_colour(state, rgba16f_, call.result.colour, pass, in_colour, out_colour);
        // The other colour buffers take the same lanes, blended the same way.
        for (size_t o = 0; o < outputs_.size(); ++o) {
            const Output& target = outputs_[o];
            for (int g = 0; g < kGroupsPerCall; ++g) {
                if (half[g] < 0) continue;  // the scratch copy, as above
                out_colour[g] = target.fb->group_colour(block[g], half[g]);
                in_colour[g] = fresh[g] ? target.clear_colour : out_colour[g];
            }
            merge_colour(state, target.rgba16f, output_values_[k][o], pass, in_colour, out_colour);
        }
    }
}

}  // namespace st
