// relief_sampled_crossing.h: the exact first crossing of a relief-mapping
// view ray with the height field as the 8-bit sampler returns it: the
// answer a linear / binary / secant search converges to, and so the
// reference its settings are chosen against (issue 28, app/quality/).
//
// relief_intersection.h crosses the bilinear surface in exact arithmetic.
// The shader never reads that surface: llvmpipe's 8-bit path (RGBA8,
// REPEAT, LINEAR; docs/llvmpipe/texture-sampling.md §1.3) takes the
// coordinate in 8.8 fixed point, round(256 x) - 128, lerps the bytes with
// 8-bit weights and blends two levels with an 8-bit weight. So what a read
// returns is constant between the points where some level's 256 x or
// 256 y crosses k + 1/2: a staircase, up to half a step from the exact
// surface. A converged search finds the staircase's crossing; against the
// exact surface's, 3.5 to 6.9 % of a relief image's pixels stay more than
// one 8-bit step off however many steps it takes (docs/relief-sweep/), an
// error no search setting can remove and so no basis for choosing one.
//
// The crossing is found without sampling error: [0, 1] is cut at every
// point where the sampler's texel changes (x = k + 127.5/256), a piece
// whose four texels of every level all lie below the ray is skipped, and
// the rest is walked step by step of the staircase, each step's height read
// once, at its middle, by the caller's sampler (`SampledHeights`). Along a
// step the height is a constant c and the ray a line, so where they meet
// is solved, not searched.
//
// The ray is the search's (relief_search.glsl): its height a + dh s at
// s in [0, 1] and a side, +1 where it crosses by reaching the surface from
// above (side * (a + dh s) <= side * h), -1 from below. A view ray from the
// top is a = 1, dh = -1, side +1.
#pragma once

#include <functional>
#include <vector>

#include "reference/relief_intersection.h"

namespace st::reference {

// Fills h[0, n) with what the sampler reads at (u[i], v[i]), n <= the batch
// size given below; the points are in t order.
using SampledHeights = std::function<void(const double* u, const double* v, int n, float* h)>;

struct SearchRay {
    double u0 = 0, v0 = 0, du = 0, dv = 0;  // at s: (u0 + s du, v0 + s dv)
    double a = 1, dh = -1, side = 1;        // height a + dh s; side as above
    // The ray starts where it just crossed (the next segment of a path
    // through a surface, a shadow ray from a hit): where it starts on the
    // crossing side, that is the crossing it leaves, and the staircase step
    // it starts in does not count; a crossing into that step from the near
    // side does (relief_sampled_crossing.cpp, `meet`).
    bool leaving = false;
};

struct SampledCrossing {
    double t = 1;         // s in [0, 1] of the crossing; 1 where there is none
    bool hit = false;
    long steps_read = 0;  // staircase steps whose height was read (the work done)
};

// The first crossing of `ray` with the staircase of `levels` (the one or
// two levels the read blends) of `field`, heights read through `heights`
// in batches of `batch` (which changes nothing but the calls). Throws
// std::invalid_argument for non-finite input, a side other than +-1, no or
// bad levels or a batch under 1; RayTooLong for a ray crossing more than
// 1e7 texel boundaries or reading more than 2e6 steps.
SampledCrossing first_sampled_crossing(const ReliefHeightField& field, const std::vector<int>& levels,
                                       const SearchRay& ray, const SampledHeights& heights, int batch);

}  // namespace st::reference
