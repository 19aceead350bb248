// triangle_setup.cpp: edge functions and bounding box on the fixed-point
// grid. Attribute planes are built by attribute_setup.cpp.
#include "raster/triangle_setup.h"

#include <algorithm>

#include "raster/attribute_setup.h"
#include "raster/fixed_point.h"

namespace st {

namespace {

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

// The edge from a to b of a triangle whose interior lies to its left (the
// caller flips clockwise triangles). Pixel centres sit at (px, py) * 256.
EdgeFunction make_edge(int64_t ax, int64_t ay, int64_t bx, int64_t by) {
    const int64_t dx = bx - ax, dy = by - ay;
    // Inward normal (-dy, dx). GL's rule as llvmpipe applies it to an FBO
    // (y up): a centre exactly on the edge is inside for left edges
    // (normal points +x) and bottom edges (horizontal, normal points +y).
    const int64_t nx = -dy, ny = dx;
    const bool inclusive = nx > 0 || (nx == 0 && ny > 0);
    EdgeFunction e;
    e.dcdx = nx * kFixedOne;
    e.dcdy = ny * kFixedOne;
    e.c = -(nx * ax + ny * ay) + (inclusive ? 1 : 0);
    return e;
}

}  // namespace

bool snappable(const SetupVertex& v0, const SetupVertex& v1, const SetupVertex& v2) {
    return snappable(v0.pos.x) && snappable(v0.pos.y) && snappable(v1.pos.x) && snappable(v1.pos.y) &&
           snappable(v2.pos.x) && snappable(v2.pos.y);
}

bool setup_triangle(const SetupVertex& v0, const SetupVertex& v1, const SetupVertex& v2,
                    int varying_count, const Interpolations& interpolation, int target_width,
                    int target_height, SetupTriangle& tri, std::vector<Plane>& planes) {
    if (!snappable(v0, v1, v2)) return false;
    const SetupVertex* v[3] = {&v0, &v1, &v2};
    int64_t x[3], y[3];
    for (int i = 0; i < 3; ++i) {
        x[i] = snap_to_subpixel(v[i]->pos.x);
        y[i] = snap_to_subpixel(v[i]->pos.y);
    }
    const int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area == 0) return false;
    tri.front_facing = area > 0;  // counter-clockwise in GL window coordinates

    const int64_t min_x = std::min({x[0], x[1], x[2]}), max_x = std::max({x[0], x[1], x[2]});
    const int64_t min_y = std::min({y[0], y[1], y[2]}), max_y = std::max({y[0], y[1], y[2]});
    tri.x_min = int(std::max<int64_t>(ceil_div(min_x, kFixedOne), 0));
    tri.y_min = int(std::max<int64_t>(ceil_div(min_y, kFixedOne), 0));
    tri.x_max = int(std::min<int64_t>(floor_div(max_x, kFixedOne), target_width - 1));
    tri.y_max = int(std::min<int64_t>(floor_div(max_y, kFixedOne), target_height - 1));
    if (tri.x_min > tri.x_max || tri.y_min > tri.y_max) return false;

    // Counter-clockwise order so that every interior lies left of its edge.
    const int o[3] = {0, area > 0 ? 1 : 2, area > 0 ? 2 : 1};
    for (int i = 0; i < 3; ++i) {
        const int a = o[i], b = o[(i + 1) % 3];
        tri.edge[i] = make_edge(x[a], y[a], x[b], y[b]);
    }

    // llvmpipe computes the area with the opposite sign (y down) and swaps
    // v0 and v1 of what it sees as clockwise triangles (lp_setup_tri.c,
    // triangle_both); the planes' reference vertex follows that swap.
    tri.first_plane = uint32_t(planes.size());
    if (area > 0) setup_attribute_planes(v1, v0, v2, varying_count, interpolation, planes);
    else setup_attribute_planes(v0, v1, v2, varying_count, interpolation, planes);
    return true;
}

}  // namespace st
