// tile_raster.cpp: edge functions stepped over the 4x4 blocks of one tile.
#include "raster/tile_raster.h"

#include <algorithm>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace st {

namespace {

// Sixteen lanes of a block, as plain vector-extension types (these are
// integers: the lane width of the shading runtime does not matter here).
// Edge values are int64: a block's sixteen lanes as two halves of eight (one
// zmm each with AVX-512; GCC splits a 16 x int64 vector badly).
using I64Half = int64_t __attribute__((vector_size(8 * kBlockLanes / 2)));
using I32Half = int32_t __attribute__((vector_size(4 * kBlockLanes / 2)));
using I32Lanes = int32_t __attribute__((vector_size(4 * kBlockLanes)));

constexpr I32Lanes kLaneX = {0, 1, 0, 1, 2, 3, 2, 3, 0, 1, 0, 1, 2, 3, 2, 3};
constexpr I32Lanes kLaneY = {0, 0, 1, 1, 0, 0, 1, 1, 2, 2, 3, 3, 2, 2, 3, 3};
constexpr I32Half kLaneXLow = {0, 1, 0, 1, 2, 3, 2, 3}, kLaneXHigh = {0, 1, 0, 1, 2, 3, 2, 3};
constexpr I32Half kLaneYLow = {0, 0, 1, 1, 0, 0, 1, 1}, kLaneYHigh = {2, 2, 3, 3, 2, 2, 3, 3};

// Bit i set where lane i is non-zero.
inline unsigned lane_bits(I32Lanes m) {
#if defined(__AVX512F__) && defined(__AVX512DQ__)
    return _mm512_movepi32_mask(__m512i(m));
#else
    unsigned bits = 0;
    for (int lane = 0; lane < kBlockLanes; ++lane) bits |= unsigned(m[lane] != 0) << lane;
    return bits;
#endif
}

static_assert(block_lane_x(5) == 3 && block_lane_y(5) == 0 && block_lane_x(10) == 0 && block_lane_y(10) == 3,
              "kLaneX/kLaneY follow shading/block_layout.h");

}  // namespace

void rasterize_in_tile(const SetupTriangle& tri, const TileRect& tile, std::vector<BlockCoverage>& out) {
    const int x_lo = std::max(tri.x_min, tile.x0) & ~3, y_lo = std::max(tri.y_min, tile.y0) & ~3;
    const int x_hi = std::min(tri.x_max, tile.x1 - 1), y_hi = std::min(tri.y_max, tile.y1 - 1);
    if (x_lo > x_hi || y_lo > y_hi) return;
    const EdgeFunction* e = tri.edge;
    // Each edge's value at every lane of a block, relative to the block's
    // corner: exact integers, so stepping equals evaluating at() per pixel.
    I64Half lane_offset[3][2];
    for (int h = 0; h < 2; ++h) {
        const I64Half lane_x = __builtin_convertvector(h ? kLaneXHigh : kLaneXLow, I64Half);
        const I64Half lane_y = __builtin_convertvector(h ? kLaneYHigh : kLaneYLow, I64Half);
        for (int i = 0; i < 3; ++i) lane_offset[i][h] = e[i].dcdx * lane_x + e[i].dcdy * lane_y;
    }
    // Over a block an edge function ranges from its corner value plus the
    // negative steps to the corner value plus the positive ones (it is
    // linear): a block all inside every edge and the box needs no per-pixel
    // test, one outside an edge none either.
    int64_t lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        lo[i] = std::min<int64_t>(0, 3 * e[i].dcdx) + std::min<int64_t>(0, 3 * e[i].dcdy);
        hi[i] = std::max<int64_t>(0, 3 * e[i].dcdx) + std::max<int64_t>(0, 3 * e[i].dcdy);
    }
    for (int y = y_lo; y <= y_hi; y += kBlockSize) {
        int64_t row[3] = {e[0].at(x_lo, y), e[1].at(x_lo, y), e[2].at(x_lo, y)};
        const bool rows_inside = y >= tri.y_min && y + kBlockSize - 1 <= y_hi;
        for (int x = x_lo; x <= x_hi; x += kBlockSize, row[0] += kBlockSize * e[0].dcdx,
                 row[1] += kBlockSize * e[1].dcdx, row[2] += kBlockSize * e[2].dcdx) {
            if (row[0] + hi[0] <= 0 || row[1] + hi[1] <= 0 || row[2] + hi[2] <= 0) continue;
            if (rows_inside && x >= tri.x_min && x + kBlockSize - 1 <= x_hi && row[0] + lo[0] > 0 &&
                row[1] + lo[1] > 0 && row[2] + lo[2] > 0) {
                out.push_back({x, y, 0xffff});
                continue;
            }
            // A partly covered block: all sixteen lanes at once.
            const I32Lanes px = x + kLaneX, py = y + kLaneY;
            const I32Lanes in_box = (px >= tri.x_min) & (px <= x_hi) & (py >= tri.y_min) & (py <= y_hi);
            I32Half in_edges[2];
            for (int h = 0; h < 2; ++h)
                in_edges[h] = __builtin_convertvector((row[0] + lane_offset[0][h] > 0) & (row[1] + lane_offset[1][h] > 0) &
                                                          (row[2] + lane_offset[2][h] > 0),
                                                      I32Half);
            const I32Lanes edges = __builtin_shufflevector(in_edges[0], in_edges[1], 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,
                                                           11, 12, 13, 14, 15);
            const unsigned mask = lane_bits(edges & in_box);
            if (mask) out.push_back({x, y, mask});
        }
    }
}

}  // namespace st
