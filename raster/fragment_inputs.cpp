// fragment_inputs.cpp: see fragment_inputs.h.
#include "raster/fragment_inputs.h"

namespace st {

namespace {

ST_INLINE Float at(const Plane& p, Float px, Float py) {
    return simd::fma(Float(p.dady), py, simd::fma(Float(p.dadx), px, Float(p.a0)));
}

}  // namespace

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

Float lane_pixel_x(int block_x, int part) {
    return Float(float(block_x)) + Float::load(kLaneOffsets.x + part * kLanes);
}

Float lane_pixel_y(int block_y, int part) {
    return Float(float(block_y)) + Float::load(kLaneOffsets.y + part * kLanes);
}

void interpolate_lanes(const Plane* planes, int varying_count, const BlockCoverage& block, int part,
                       bool front_facing, FragmentLanes& out) {
    const Plane& z_plane = planes[0];
    const Plane& inv_w_plane = planes[1];
    const Plane* varying_planes = planes + 2;
    out.front_facing = front_facing;
    out.covered = Mask::from_bits(block.mask >> (part * kLanes));
    const Float px = lane_pixel_x(block.x, part), py = lane_pixel_y(block.y, part);
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
