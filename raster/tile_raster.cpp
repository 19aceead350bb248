// tile_raster.cpp: edge functions stepped over the 4x4 blocks of one tile.
#include "raster/tile_raster.h"

#include <algorithm>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace st {

namespace {

// Edge values are int64 (the fixed-point products exceed 32 bits). A partly
// covered block tests its sixteen lanes in chunks of the widest int64 vector
// the target holds in one register: 8 with AVX-512, 4 otherwise. (A wider
// vector-extension type than the registers is split by GCC through the
// stack: on AVX2 the 8-lane halves this used to take spent most of the
// function's time in spills.)
#if defined(__AVX512F__) && defined(__AVX512DQ__)
constexpr int kChunkLanes = 8;
#else
constexpr int kChunkLanes = 4;
#endif
constexpr int kChunks = kBlockLanes / kChunkLanes;
using I64Chunk = int64_t __attribute__((vector_size(8 * kChunkLanes)));

// Bit j set where lane j of the chunk is non-zero (all ones or zero).
inline unsigned chunk_bits(I64Chunk m) {
#if defined(__AVX512F__) && defined(__AVX512DQ__)
    return _mm512_movepi64_mask(__m512i(m));
#elif defined(__AVX2__)
    return unsigned(_mm256_movemask_pd(_mm256_castsi256_pd(__m256i(m))));
#else
    unsigned bits = 0;
    for (int j = 0; j < kChunkLanes; ++j) bits |= unsigned(m[j] != 0) << j;
    return bits;
#endif
}

// The lanes of a block in column dx, and in row dy (shading/block_layout.h).
constexpr unsigned lanes_where(bool column, int d) {
    unsigned bits = 0;
    for (int lane = 0; lane < kBlockLanes; ++lane)
        if ((column ? block_lane_x(lane) : block_lane_y(lane)) == d) bits |= 1u << lane;
    return bits;
}
constexpr unsigned kColumnLanes[kBlockSize] = {lanes_where(true, 0), lanes_where(true, 1), lanes_where(true, 2),
                                               lanes_where(true, 3)};
constexpr unsigned kRowLanes[kBlockSize] = {lanes_where(false, 0), lanes_where(false, 1), lanes_where(false, 2),
                                            lanes_where(false, 3)};
static_assert(kColumnLanes[1] == 0x0a0a && kRowLanes[3] == 0xcc00, "block_layout.h's lane order");

// The lanes of the block at (x, y) whose pixels lie in [x_lo, x_hi] x
// [y_lo, y_hi], inclusive.
inline unsigned box_lanes(int x, int y, int x_lo, int x_hi, int y_lo, int y_hi) {
    unsigned columns = 0, rows = 0;
    for (int d = 0; d < kBlockSize; ++d) {
        if (x + d >= x_lo && x + d <= x_hi) columns |= kColumnLanes[d];
        if (y + d >= y_lo && y + d <= y_hi) rows |= kRowLanes[d];
    }
    return columns & rows;
}

}  // namespace

void rasterize_in_tile(const SetupTriangle& tri, const TileRect& tile, std::vector<BlockCoverage>& out) {
    const int x_lo = std::max(tri.x_min, tile.x0) & ~3, y_lo = std::max(tri.y_min, tile.y0) & ~3;
    const int x_hi = std::min(tri.x_max, tile.x1 - 1), y_hi = std::min(tri.y_max, tile.y1 - 1);
    if (x_lo > x_hi || y_lo > y_hi) return;
    const EdgeFunction* e = tri.edge;
    // Each edge's value at every lane of a block, relative to the block's
    // corner: exact integers, so stepping equals evaluating at() per pixel.
    I64Chunk lane_offset[3][kChunks];
    for (int i = 0; i < 3; ++i)
        for (int c = 0; c < kChunks; ++c)
            for (int j = 0; j < kChunkLanes; ++j) {
                const int lane = c * kChunkLanes + j;
                lane_offset[i][c][j] = e[i].dcdx * block_lane_x(lane) + e[i].dcdy * block_lane_y(lane);
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
            // A partly covered block: every lane against the three edges.
            unsigned edges = 0;
            for (int c = 0; c < kChunks; ++c) {
                const I64Chunk inside = (row[0] + lane_offset[0][c] > 0) & (row[1] + lane_offset[1][c] > 0) &
                                        (row[2] + lane_offset[2][c] > 0);
                edges |= chunk_bits(inside) << (c * kChunkLanes);
            }
            const unsigned mask = edges & box_lanes(x, y, tri.x_min, x_hi, tri.y_min, y_hi);
            if (mask) out.push_back({x, y, mask});
        }
    }
}

}  // namespace st
