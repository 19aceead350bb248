// clipper.h: geometric clipping against the view volume, as llvmpipe's draw
// module does it (draw_pipe_clip.c), so that clipped triangles get the same
// new vertices, in the same order, on both backends.
//
// llvmpipe has no guard band for our float targets: x, y and z are all
// clipped at -w..w. A triangle with every vertex inside passes unchanged
// (its vertices keep the fused viewport transform of viewport.h); one with
// all vertices outside the same plane is dropped; any other is clipped one
// plane at a time in the order right, left, top, bottom, near, far, and the
// vertices made by clipping get an unfused viewport transform (C code in
// Mesa). Numbers: ../shared/notes/llvmpipe.md and docs/architecture.md.
#pragma once

#include <vector>

#include "shading/program.h"
#include "raster/viewport.h"

namespace st {

struct ClipVertex {
    VertexOut out;     // clip position and varyings
    WindowPos window;  // its window coordinates
};

// Outcode bits: 0 x > w, 1 x + w < 0, 2 y > w, 3 y + w < 0, 4 z + w < 0,
// 5 z > w. A NaN coordinate sets the bits that involve it.
unsigned clip_mask(const glm::vec4& clip);

// Clips triangle (a, b, c), whose outcodes OR to `mask_or` (non-zero), and
// appends the resulting triangles to `out` (three ClipVertex each), fanned
// as llvmpipe fans them for GL's last-vertex provoking convention. Appends
// nothing when the triangle vanishes or a plane distance is not finite.
// Each varying slot is carried as `interpolation` says (make_vertex in
// clipper.cpp); c is the provoking vertex of flat ones.
void clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, unsigned mask_or,
                   int varying_count, const Interpolations& interpolation, const Viewport& viewport,
                   std::vector<ClipVertex>& out);

}  // namespace st
