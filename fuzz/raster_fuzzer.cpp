// raster_fuzzer.cpp: clipping, triangle setup and tile rasterization on any
// vertices (random, degenerate, huge, NaN, infinite, denormal w), checked
// against a reference rule for coverage.
//
// The reference evaluates GL's rule directly at every pixel centre of the
// target, in 128-bit integers on the snapped grid (fixed_point.h): a centre
// is covered when it lies strictly left of every counter-clockwise edge, or
// on an edge whose inward normal points +x, or +y for a horizontal edge.
// The rasterizer must cover exactly those pixels, nothing outside the target,
// and no pixel twice; a triangle that cannot be snapped must be dropped.
//
// An input: target width and height (1..160), then triangles, each a mode
// byte (clip-space vertices through the clipper, or window positions
// straight into setup) and its coordinates; each coordinate is a tag byte
// choosing raw float bits, a small grid value or a special value.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "raster/clipper.h"
#include "raster/fixed_point.h"
#include "raster/tile_raster.h"
#include "raster/triangle_setup.h"
#include "raster/viewport.h"

namespace {

using namespace st;

struct Reader {
    const uint8_t* data;
    size_t size, at = 0;
    uint8_t byte() { return at < size ? data[at++] : 0; }
    bool done() const { return at >= size; }
    float coordinate(bool clip) {
        const uint8_t tag = byte();
        switch (tag % 4) {
            case 0: {  // any bits at all
                uint32_t bits = 0;
                for (int i = 0; i < 4; ++i) bits |= uint32_t(byte()) << (8 * i);
                float f;
                std::memcpy(&f, &bits, 4);
                return f;
            }
            case 1:  // a small grid: clip units in eighths, pixels in quarters and sub-pixel steps
                return clip ? float(int(byte()) - 128) / 64.0f : float(int(byte()) - 32) / 4.0f + float(tag >> 2) / 256.0f;
            case 2: {
                static const float kSpecial[] = {
                    0.0f, -0.0f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                    std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::max(),
                    -std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(),
                    -std::numeric_limits<float>::denorm_min(), 1e-38f, kMaxWindowCoord, std::nextafter(kMaxWindowCoord, 2e6f),
                    -kMaxWindowCoord, 1.0f, -1.0f, 16384.5f, 0.5f, 1e-30f, 1.0f + 1e-7f, 2.0f};
                return kSpecial[byte() % (sizeof kSpecial / sizeof kSpecial[0])];
            }
            default:  // pixel centres and the half-way points between them
                return float(int(byte()) - 16) * 0.5f;
        }
    }
};

// GL's coverage rule for one pixel centre on the snapped grid (see above).
bool reference_covers(const int64_t (&x)[3], const int64_t (&y)[3], int px, int py) {
    const __int128 area = __int128(x[1] - x[0]) * (y[2] - y[0]) - __int128(x[2] - x[0]) * (y[1] - y[0]);
    if (area == 0) return false;
    const int order[3] = {0, area > 0 ? 1 : 2, area > 0 ? 2 : 1};
    const int64_t cx = int64_t(px) * kFixedOne, cy = int64_t(py) * kFixedOne;
    for (int i = 0; i < 3; ++i) {
        const int a = order[i], b = order[(i + 1) % 3];
        const int64_t ex = x[b] - x[a], ey = y[b] - y[a];
        const __int128 side = __int128(ex) * (cy - y[a]) - __int128(ey) * (cx - x[a]);  // > 0: left of a->b
        if (side > 0) continue;
        if (side < 0) return false;
        const int64_t nx = -ey, ny = ex;  // inward normal
        if (!(nx > 0 || (nx == 0 && ny > 0))) return false;
    }
    return true;
}

size_t g_triangles = 0, g_rasterized = 0;
struct Totals {
    ~Totals() { std::fprintf(stderr, "raster_fuzzer: %zu triangles set up, %zu rasterized\n", g_triangles, g_rasterized); }
} g_totals;

int64_t floor_div256(int64_t v) { return v >= 0 ? v / kFixedOne : -((-v + kFixedOne - 1) / kFixedOne); }

void check_triangle(const SetupVertex& a, const SetupVertex& b, const SetupVertex& c, int width, int height) {
    ++g_triangles;
    SetupTriangle tri;
    std::vector<Plane> planes;
    const bool kept = setup_triangle(a, b, c, 1, Interpolations{}, width, height, tri, planes);
    // The reference's pixels, in a width x height grid. Only centres within
    // the snapped vertices' box can be covered, so only those are tested.
    std::vector<uint8_t> want(size_t(width) * size_t(height), 0);
    size_t want_count = 0;
    if (snappable(a, b, c)) {
        const int64_t x[3] = {snap_to_subpixel(a.pos.x), snap_to_subpixel(b.pos.x), snap_to_subpixel(c.pos.x)};
        const int64_t y[3] = {snap_to_subpixel(a.pos.y), snap_to_subpixel(b.pos.y), snap_to_subpixel(c.pos.y)};
        const int64_t x0 = std::max<int64_t>(0, -floor_div256(-std::min({x[0], x[1], x[2]})));
        const int64_t y0 = std::max<int64_t>(0, -floor_div256(-std::min({y[0], y[1], y[2]})));
        const int64_t x1 = std::min<int64_t>(width - 1, floor_div256(std::max({x[0], x[1], x[2]})));
        const int64_t y1 = std::min<int64_t>(height - 1, floor_div256(std::max({y[0], y[1], y[2]})));
        for (int64_t py = y0; py <= y1; ++py)
            for (int64_t px = x0; px <= x1; ++px)
                if (reference_covers(x, y, int(px), int(py))) {
                    want[size_t(py) * size_t(width) + size_t(px)] = 1;
                    ++want_count;
                }
    } else if (kept) {
        std::abort();  // an unsnappable triangle must be dropped
    }
    if (!kept) {
        if (want_count) std::abort();  // dropped, but it covers a pixel centre
        return;
    }
    ++g_rasterized;
    size_t got_count = 0;
    std::vector<BlockCoverage> blocks;
    for (int ty = tri.y_min / kTileSize; ty <= tri.y_max / kTileSize; ++ty)
        for (int tx = tri.x_min / kTileSize; tx <= tri.x_max / kTileSize; ++tx) {
            const TileRect rect{tx * kTileSize, ty * kTileSize, std::min(width, (tx + 1) * kTileSize),
                                std::min(height, (ty + 1) * kTileSize)};
            blocks.clear();
            rasterize_in_tile(tri, rect, blocks);
            for (const BlockCoverage& block : blocks)
                for (int lane = 0; lane < kBlockLanes; ++lane)
                    if (block.mask >> lane & 1) {
                        const int px = block.x + block_lane_x(lane), py = block.y + block_lane_y(lane);
                        if (px < rect.x0 || px >= rect.x1 || py < rect.y0 || py >= rect.y1) std::abort();
                        uint8_t& seen = want[size_t(py) * size_t(width) + size_t(px)];
                        if (seen != 1) std::abort();  // not the reference's, or covered twice
                        seen = 2;
                        ++got_count;
                    }
        }
    if (got_count != want_count) std::abort();  // a pixel of the reference's left out
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Reader in{data, size};
    const int width = 1 + in.byte() % 160, height = 1 + in.byte() % 160;
    const Viewport viewport{0, 0, float(width), float(height), 0, 1};
    static const glm::vec4 kNoVaryings[1] = {glm::vec4(0)};
    std::vector<ClipVertex> clipped;
    for (int t = 0; t < 64 && !in.done(); ++t) {
        const bool clip = in.byte() & 1;
        if (!clip) {
            SetupVertex v[3];
            for (auto& vertex : v) {
                const float x = in.coordinate(false), y = in.coordinate(false);
                vertex = SetupVertex{WindowPos{x, y, 0.5f, 1.0f}, kNoVaryings};
            }
            check_triangle(v[0], v[1], v[2], width, height);
            continue;
        }
        ClipVertex v[3];
        unsigned mask_or = 0, mask_and = ~0u;
        for (auto& vertex : v) {
            for (int k = 0; k < 4; ++k) vertex.out.position[k] = in.coordinate(true);
            vertex.out.varyings[0] = vertex.out.position;
            vertex.window = to_window(vertex.out.position, viewport);
            const unsigned mask = clip_mask(vertex.out.position);
            mask_or |= mask;
            mask_and &= mask;
        }
        if (mask_and) continue;
        if (!mask_or) {
            check_triangle({v[0].window, v[0].out.varyings.data()}, {v[1].window, v[1].out.varyings.data()},
                           {v[2].window, v[2].out.varyings.data()}, width, height);
            continue;
        }
        // Slot 1 noperspective, slot 2 flat: every triangle the clipper
        // makes must end in a vertex carrying c's flat bits (GL's provoking
        // vertex), whatever the positions, NaN and infinity included.
        for (int k = 0; k < 3; ++k) {
            v[k].out.varyings[1] = v[k].out.position;
            v[k].out.varyings[2] = glm::vec4(std::bit_cast<float>(0x7F800001u + uint32_t(k)));
        }
        Interpolations modes{};
        modes[1] = Interpolation::NoPerspective;
        modes[2] = Interpolation::Flat;
        clipped.clear();
        clip_triangle(v[0], v[1], v[2], mask_or, 3, modes, viewport, clipped);
        if (clipped.size() % 3) std::abort();
        for (size_t k = 0; k + 2 < clipped.size(); k += 3)
            if (std::bit_cast<uint32_t>(clipped[k + 2].out.varyings[2].x) != 0x7F800003u) std::abort();
        for (size_t k = 0; k + 2 < clipped.size(); k += 3)
            check_triangle({clipped[k].window, clipped[k].out.varyings.data()},
                           {clipped[k + 1].window, clipped[k + 1].out.varyings.data()},
                           {clipped[k + 2].window, clipped[k + 2].out.varyings.data()}, width, height);
    }
    return 0;
}
