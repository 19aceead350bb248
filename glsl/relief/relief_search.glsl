// relief_search.glsl: a ray traced into a relief map's height field
// (Timonen Sec. 3: "linear search is used to close in on the intersection
// range and binary search is used to refine the range. Linear height field
// approximation is used to compute the final intersection coordinates").
// The ray enters the layer's box at its top (height 1) at `uv` and reaches
// its floor (height 0) at uv + offset; t in [0, 1] is the fraction of the
// depth travelled, so the ray is at height 1 - t. Heights are read with the
// entry point's derivatives (textureGrad), so that every step of a quad
// reads the level its entry reads. Twin: kernels/relief/relief_search.cpp.

// The first point where a ray segment through a layer's box crosses the
// surface: it starts at `uv` at height `a` (in the layer's units) and ends
// at uv + offset at height a + dh. With side = 1 the ray starts above the
// surface and the crossing is the first point at or below it; with
// side = -1 it starts below (inside a medium) and the crossing is the first
// point at or above it (multiplying both sides by 1 changes no bit). s in
// [0, 1] is the fraction of the segment: linear_steps equal steps until
// the ray has crossed, binary_steps halvings of that last step, then, if
// `secant`, the zero of the straight line through the ray-minus-surface
// differences at the bracket's ends. `hit` is false when the segment never
// crosses (a rising ray leaves the box); then s is 1.
float trace_segment(sampler2D map, vec2 uv, vec2 offset, float a, float dh, float side, vec2 dx, vec2 dy,
                    int linear_steps, int binary_steps, bool secant, out bool hit) {
    float size = 1.0 / float(linear_steps);
    float s = 0.0;
    float h = textureGrad(map, uv, dx, dy).a;
    float h_prev = h;
    for (int i = 0; i < linear_steps; ++i) {
        h_prev = h;
        s += size;
        h = textureGrad(map, uv + offset * s, dx, dy).a;
        if (side * (a + dh * s) <= side * h) break;
    }
    // The loop breaks exactly where this holds; a ray that never met the
    // surface ends at s = 1 above it.
    hit = side * (a + dh * s) <= side * h;
    float s_lo = s - size;
    float s_hi = s;
    float h_lo = h_prev;
    float h_hi = h;
    for (int i = 0; i < binary_steps; ++i) {
        float mid = 0.5 * (s_lo + s_hi);
        float h_mid = textureGrad(map, uv + offset * mid, dx, dy).a;
        bool below = side * (a + dh * mid) <= side * h_mid;
        s_hi = below ? mid : s_hi;
        h_hi = below ? h_mid : h_hi;
        s_lo = below ? s_lo : mid;
        h_lo = below ? h_lo : h_mid;
    }
    // Before the crossing at s_lo (d_lo >= 0), past it at s_hi (d_hi <= 0)
    // when there is a hit; when the line has no zero in the bracket, s_hi
    // stands. A segment that starts past the surface already (d_lo < 0: a
    // refracted ray leaving a medium's hit below the solid layer) would put
    // the line's zero behind its start, and a negative length through the
    // medium then absorbs to infinity: the zero is kept within the bracket.
    float d_lo = side * ((a + dh * s_lo) - h_lo);
    float d_hi = side * ((a + dh * s_hi) - h_hi);
    float denom = d_lo - d_hi;
    float s_line = s_lo + (s_hi - s_lo) * (d_lo / denom);
    float s_secant = denom > 0.0 ? min(max(s_line, s_lo), s_hi) : s_hi;
    return secant && hit ? s_secant : s_hi;
}

// Whether a rising segment (side 1) meets the surface at all: the linear
// search alone, as a shadow test needs no refined point (Policarpo et al.'s
// self-shadowing does the same); the same answer as trace_segment's `hit`.
bool segment_blocked(sampler2D map, vec2 uv, vec2 offset, float a, float dh, vec2 dx, vec2 dy, int linear_steps) {
    float size = 1.0 / float(linear_steps);
    float s = 0.0;
    float h = textureGrad(map, uv, dx, dy).a;
    for (int i = 0; i < linear_steps; ++i) {
        s += size;
        h = textureGrad(map, uv + offset * s, dx, dy).a;
        if (a + dh * s <= h) break;
    }
    return a + dh * s <= h;
}

// The view ray from the top of the box (height 1) at uv down to its floor
// (height 0) at uv + offset: the floor stops every such ray, so it always
// hits; t is the fraction of the depth travelled.
float trace_height_field(sampler2D map, vec2 uv, vec2 offset, vec2 dx, vec2 dy, int linear_steps,
                         int binary_steps, bool secant) {
    bool hit;
    return trace_segment(map, uv, offset, 1.0, -1.0, 1.0, dx, dy, linear_steps, binary_steps, secant, hit);
}
