// clipper.cpp: Sutherland-Hodgman against two planes.
#include "raster/clipper.h"

namespace st {

namespace {

// Signed distances: >= 0 inside.
float near_distance(const glm::vec4& p) { return p.z + p.w; }
float far_distance(const glm::vec4& p) { return p.w - p.z; }

VertexOut interpolate(const VertexOut& in, const VertexOut& out, float t, int varying_count) {
    VertexOut v;
    v.position = in.position + (out.position - in.position) * t;
    for (int s = 0; s < varying_count; ++s)
        v.varyings[s] = in.varyings[s] + (out.varyings[s] - in.varyings[s]) * t;
    return v;
}

// Always interpolates from the inside vertex towards the outside one, so an
// edge shared by two triangles yields the same new vertex in both.
void clip_plane(const std::vector<VertexOut>& src, float (*distance)(const glm::vec4&),
                int varying_count, std::vector<VertexOut>& dst) {
    dst.clear();
    for (size_t i = 0; i < src.size(); ++i) {
        const VertexOut& cur = src[i];
        const VertexOut& next = src[(i + 1) % src.size()];
        const float dc = distance(cur.position), dn = distance(next.position);
        if (dc >= 0) dst.push_back(cur);
        if ((dc >= 0) != (dn >= 0)) {
            if (dc >= 0) dst.push_back(interpolate(cur, next, dc / (dc - dn), varying_count));
            else dst.push_back(interpolate(next, cur, dn / (dn - dc), varying_count));
        }
    }
}

}  // namespace

void clip_near_far(const VertexOut& a, const VertexOut& b, const VertexOut& c, int varying_count,
                   std::vector<VertexOut>& polygon) {
    std::vector<VertexOut> tmp{a, b, c};
    clip_plane(tmp, near_distance, varying_count, polygon);
    if (polygon.size() < 3) {
        polygon.clear();
        return;
    }
    tmp.swap(polygon);
    clip_plane(tmp, far_distance, varying_count, polygon);
    if (polygon.size() < 3) polygon.clear();
}

}  // namespace st
