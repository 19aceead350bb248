// fragment_inputs.cpp: see fragment_inputs.h.
#include "raster/fragment_inputs.h"

#include <algorithm>

#include "shading/block_layout.h"

namespace st {

namespace {

ST_INLINE Float at(const Plane& p, Float px, Float py) {
    return simd::fma(Float(p.dady), py, simd::fma(Float(p.dadx), px, Float(p.a0)));
}

// Each lane's pixel offset inside the block, as floats (exact).
struct LaneOffsets {
    float x[kBlockLanes], y[kBlockLanes];
    constexpr LaneOffsets() : x(), y() {
        for (int lane = 0; lane < kBlockLanes; ++lane) {
            x[lane] = float(block_lane_x(lane));
            y[lane] = float(block_lane_y(lane));
        }
    }
};
constexpr LaneOffsets kLaneOffsets;

}  // namespace

void interpolate_lanes(const Plane* planes, int varying_count, const LaneGroup* groups, bool front_facing,
                       FragmentLanes& out) {
    const Plane& z_plane = planes[0];
    const Plane& inv_w_plane = planes[1];
    const Plane* varying_planes = planes + 2;
    constexpr int kGroups = kLanes / kGroupLanes;
    // Pixel indices of every lane: the group's block corner plus the lane's
    // offset in the block (small integers, exact in float).
    float corner_x[kLanes], corner_y[kLanes];
    const float* offset_x[kGroups];
    const float* offset_y[kGroups];
    unsigned covered = 0;
    for (int g = 0; g < kGroups; ++g) {
        std::fill_n(corner_x + g * kGroupLanes, kGroupLanes, float(groups[g].x));
        std::fill_n(corner_y + g * kGroupLanes, kGroupLanes, float(groups[g].y));
        offset_x[g] = kLaneOffsets.x + groups[g].half * kGroupLanes;
        offset_y[g] = kLaneOffsets.y + groups[g].half * kGroupLanes;
        covered |= groups[g].mask << (g * kGroupLanes);
    }
    const Float px = Float::load(corner_x) + Float::load_groups(offset_x);
    const Float py = Float::load(corner_y) + Float::load_groups(offset_y);
    out.front_facing = front_facing;
    out.covered = Mask::from_bits(covered);
    // Depth is clamped to the depth range [0, 1] before the test (a NaN
    // stays NaN, as std::clamp leaves it).
    const Float z_raw = at(z_plane, px, py);
    const Float z = select(z_raw < Float(0.0f), Float(0.0f), select(Float(1.0f) < z_raw, Float(1.0f), z_raw));
    const Float inv_w = at(inv_w_plane, px, py);
    const Float w = Float(1.0f) / inv_w;
    out.frag_coord = Vec4(px + Float(0.5f), py + Float(0.5f), z, inv_w);
    for (int slot = 0; slot < varying_count; ++slot) {
        const Plane* p = varying_planes + slot * 4;
        out.varyings[size_t(slot)] = Vec4(at(p[0], px, py) * w, at(p[1], px, py) * w, at(p[2], px, py) * w,
                                          at(p[3], px, py) * w);
    }
}

}  // namespace st
