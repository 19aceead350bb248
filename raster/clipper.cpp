// clipper.cpp: Sutherland-Hodgman with llvmpipe's choices of interpolation
// direction and fan order (see clipper.h).
#include "raster/clipper.h"

#include <cmath>

namespace st {

namespace {

// Signed distance to plane i (>= 0 inside): the dot product with the plane's
// coefficients in Mesa reduces to one rounded add or subtract.
float plane_distance(const glm::vec4& p, int plane) {
    switch (plane) {
        case 0: return p.w - p.x;
        case 1: return p.x + p.w;
        case 2: return p.w - p.y;
        case 3: return p.y + p.w;
        case 4: return p.z + p.w;
        default: return p.w - p.z;
    }
}

// dst = from + t * (to - from), three rounded operations per component.
glm::vec4 lerp_unfused(const glm::vec4& from, const glm::vec4& to, float t) {
    glm::vec4 r;
    for (int i = 0; i < 4; ++i) {
        const float d = to[i] - from[i];
        const float td = t * d;
        r[i] = from[i] + td;
    }
    return r;
}

// The new vertex on the segment from `from` towards `to` at parameter t, with
// Mesa's C viewport transform: ((x * (1/w)) * scale) + translate, unfused.
// Smooth varyings are interpolated with t, noperspective ones with the
// window-space parameter of the same point; flat ones are not interpolated
// (draw_pipe_clip.c, interp): only the fan's provoking vertex carries them,
// and clip_triangle copies them there.
ClipVertex make_vertex(const ClipVertex& from, const ClipVertex& to, float t, int varying_count,
                       const Interpolations& interpolation, const Viewport& vp) {
    ClipVertex v;
    v.out.position = lerp_unfused(from.out.position, to.out.position, t);
    const glm::vec4 &p0 = from.out.position, &p1 = to.out.position, &p = v.out.position;
    bool have_window_t = false;
    float window_t = t;
    for (int s = 0; s < varying_count; ++s) {
        switch (interpolation[size_t(s)]) {
            case Interpolation::Smooth:
                v.out.varyings[s] = lerp_unfused(from.out.varyings[s], to.out.varyings[s], t);
                break;
            case Interpolation::NoPerspective:
                if (!have_window_t) {
                    // The first of x, y in which the endpoints differ; when
                    // neither does, the point is degenerate and t serves.
                    have_window_t = true;
                    for (int k = 0; k < 2; ++k)
                        if (p1[k] != p0[k]) {
                            const float c0 = p0[k] / p0.w, c1 = p1[k] / p1.w, c = p[k] / p.w;
                            window_t = (c - c0) / (c1 - c0);
                            break;
                        }
                }
                v.out.varyings[s] = lerp_unfused(from.out.varyings[s], to.out.varyings[s], window_t);
                break;
            case Interpolation::Flat:
                v.out.varyings[s] = from.out.varyings[s];  // never read (see above)
                break;
        }
    }
    const float scale_x = vp.width * 0.5f, trans_x = vp.x0 + vp.width * 0.5f;
    const float scale_y = vp.height * 0.5f, trans_y = vp.y0 + vp.height * 0.5f;
    const float scale_z = (vp.far - vp.near) * 0.5f, trans_z = (vp.far + vp.near) * 0.5f;
    const float oow = 1.0f / p.w;
    const float x = (p.x * oow) * scale_x, y = (p.y * oow) * scale_y, z = (p.z * oow) * scale_z;
    v.window = WindowPos{x + trans_x, y + trans_y, z + trans_z, oow};
    return v;
}

}  // namespace

unsigned clip_mask(const glm::vec4& p) {
    unsigned m = 0;
    // Written as negated "inside" tests so that NaN counts as outside.
    m |= unsigned(!(p.x <= p.w)) << 0;
    m |= unsigned(!(p.x + p.w >= 0.0f)) << 1;
    m |= unsigned(!(p.y <= p.w)) << 2;
    m |= unsigned(!(p.y + p.w >= 0.0f)) << 3;
    m |= unsigned(!(p.z + p.w >= 0.0f)) << 4;
    m |= unsigned(!(p.z <= p.w)) << 5;
    return m;
}

void clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, unsigned mask_or,
                   int varying_count, const Interpolations& interpolation, const Viewport& viewport,
                   std::vector<ClipVertex>& out) {
    // Polygon vertices live in `pool`; lists hold indices into it.
    std::vector<ClipVertex> pool{a, b, c};
    std::vector<int> in{0, 1, 2}, next;
    for (int plane = 0; plane < 6 && in.size() >= 3; ++plane) {
        if (!(mask_or >> plane & 1)) continue;
        next.clear();
        in.push_back(in[0]);  // close the loop; keeps the first vertex first
        float dp_prev = plane_distance(pool[size_t(in[0])].out.position, plane);
        if (!std::isfinite(dp_prev)) return;
        for (size_t i = 1; i < in.size(); ++i) {
            const int prev = in[i - 1], cur = in[i];
            const float dp = plane_distance(pool[size_t(cur)].out.position, plane);
            if (!std::isfinite(dp)) return;
            bool crosses;
            if (dp_prev >= 0.0f) {
                next.push_back(prev);
                crosses = dp < 0.0f;
            } else {
                crosses = !(dp < 0.0f);
            }
            if (crosses) {
                // Interpolate from the endpoint nearer the plane, so t <= 0.5
                // and a shared edge gives the same vertex from either side.
                const float denom = dp - dp_prev;
                const ClipVertex &p = pool[size_t(prev)], &q = pool[size_t(cur)];
                ClipVertex v;
                if (dp < 0.0f) {  // going out
                    v = (-dp < dp_prev) ? make_vertex(q, p, dp / denom, varying_count, interpolation, viewport)
                                        : make_vertex(p, q, -dp_prev / denom, varying_count, interpolation, viewport);
                } else {          // coming back in
                    v = (-dp_prev < dp) ? make_vertex(p, q, -dp_prev / denom, varying_count, interpolation, viewport)
                                        : make_vertex(q, p, dp / denom, varying_count, interpolation, viewport);
                }
                next.push_back(int(pool.size()));
                pool.push_back(v);
            }
            dp_prev = dp;
        }
        in.swap(next);
    }
    if (in.size() < 3) return;
    // GL's provoking vertex is the last: triangles (i-1, i, 0). The
    // polygon's first vertex provokes them all, so it gets the flat values
    // of the original provoking vertex c (pool[2]) when it is another one.
    if (in[0] != 2)
        for (int s = 0; s < varying_count; ++s)
            if (interpolation[size_t(s)] == Interpolation::Flat)
                pool[size_t(in[0])].out.varyings[s] = pool[2].out.varyings[s];
    for (size_t i = 2; i < in.size(); ++i) {
        out.push_back(pool[size_t(in[i - 1])]);
        out.push_back(pool[size_t(in[i])]);
        out.push_back(pool[size_t(in[0])]);
    }
}

}  // namespace st
