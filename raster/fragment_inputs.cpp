// fragment_inputs.cpp: see fragment_inputs.h.
#include "raster/fragment_inputs.h"

#include <algorithm>
#include <limits>

#include "shading/block_layout.h"

namespace st {

namespace {

ST_INLINE Float at(const Plane& p, Float px, Float py) {
    return simd::fmuladd(Float(p.dady), py, simd::fmuladd(Float(p.dadx), px, Float(p.a0)));
}

// Each lane's pixel offset inside its block, as floats (exact), for every
// choice of halves of the call's groups: one aligned load per call.
constexpr int kGroups = kLanes / kGroupLanes;
struct LaneOffsets {
    alignas(64) float x[1 << kGroups][kLanes];
    alignas(64) float y[1 << kGroups][kLanes];
    constexpr LaneOffsets() : x(), y() {
        for (int halves = 0; halves < (1 << kGroups); ++halves)
            for (int lane = 0; lane < kLanes; ++lane) {
                const int half = halves >> (lane / kGroupLanes) & 1;
                x[halves][lane] = float(block_lane_x(half * kGroupLanes + lane % kGroupLanes));
                y[halves][lane] = float(block_lane_y(half * kGroupLanes + lane % kGroupLanes));
            }
    }
};
constexpr LaneOffsets kLaneOffsets;

// A per-group value in each group's lanes.
ST_INLINE Float per_group(const LaneGroup* groups, int LaneGroup::*field) {
    Float r(float(groups[0].*field));
    for (int g = 1; g < kGroups; ++g) {
        const Mask upper = Mask::from_bits(~0u << (g * kGroupLanes));
        r = select(upper, Float(float(groups[g].*field)), r);
    }
    return r;
}

}  // namespace

void interpolate_lanes(const Plane* planes, int varying_count, uint32_t components,
                       const Interpolations& interpolation, const LaneGroup* groups, bool front_facing,
                       FragmentLanes& out) {
    const Plane& z_plane = planes[0];
    const Plane& inv_w_plane = planes[1];
    const Plane* varying_planes = planes + 2;
    // Pixel indices of every lane: the group's block corner plus the lane's
    // offset in the block (small integers, exact in float).
    int halves = 0;
    unsigned covered = 0;
    for (int g = 0; g < kGroups; ++g) {
        halves |= groups[g].half << g;
        covered |= groups[g].mask << (g * kGroupLanes);
    }
    const Float px = per_group(groups, &LaneGroup::x) + Float::load(kLaneOffsets.x[halves]);
    const Float py = per_group(groups, &LaneGroup::y) + Float::load(kLaneOffsets.y[halves]);
    out.front_facing = front_facing;
    out.covered = Mask::from_bits(covered);
    // Depth is clamped to the depth range [0, 1] before the test (a NaN
    // stays NaN, as std::clamp leaves it).
    const Float z_raw = at(z_plane, px, py);
    const Float z = select(z_raw < Float(0.0f), Float(0.0f), select(Float(1.0f) < z_raw, Float(1.0f), z_raw));
    const Float inv_w = at(inv_w_plane, px, py);
    const Float w = Float(1.0f) / inv_w;
    out.frag_coord = Vec4(px + Float(0.5f), py + Float(0.5f), z, inv_w);
    const Float not_read(std::numeric_limits<float>::quiet_NaN());
    for (int slot = 0; slot < varying_count; ++slot) {
        const Plane* p = varying_planes + slot * 4;
        static constexpr Float Vec4::*kComponent[4] = {&Vec4::x, &Vec4::y, &Vec4::z, &Vec4::w};
        const Interpolation mode = interpolation[size_t(slot)];
        for (int c = 0; c < 4; ++c) {
            Float& v = out.varyings[size_t(slot)].*kComponent[c];
            if (!(components >> (4 * slot + c) & 1)) v = not_read;
            else if (mode == Interpolation::Smooth) v = at(p[c], px, py) * w;
            else if (mode == Interpolation::NoPerspective) v = at(p[c], px, py);
            else v = Float(p[c].a0);
        }
    }
}

}  // namespace st
