// relief_search.glsl: a ray traced into a relief map's height field
// (Timonen Sec. 3: "linear search is used to close in on the intersection
// range and binary search is used to refine the range. Linear height field
// approximation is used to compute the final intersection coordinates").
// The ray enters the layer's box at its top (height 1) at `uv` and reaches
// its floor (height 0) at uv + offset; t in [0, 1] is the fraction of the
// depth travelled, so the ray is at height 1 - t. Heights are read with the
// entry point's derivatives (textureGrad), so that every step of a quad
// reads the level its entry reads. Twin: kernels/relief/relief_search.cpp.

// The t of the first hit: linear_steps equal steps until the ray is at or
// below the surface (the floor stops every ray), binary_steps halvings of
// that last step, then, if `secant`, the zero of the straight line through
// the ray-minus-surface differences at the bracket's ends.
float trace_height_field(sampler2D map, vec2 uv, vec2 offset, vec2 dx, vec2 dy, int linear_steps,
                         int binary_steps, bool secant) {
    float size = 1.0 / float(linear_steps);
    float t = 0.0;
    float h = textureGrad(map, uv, dx, dy).a;
    float h_prev = h;
    for (int i = 0; i < linear_steps; ++i) {
        h_prev = h;
        t += size;
        h = textureGrad(map, uv + offset * t, dx, dy).a;
        if (1.0 - t <= h) break;
    }
    float t_lo = t - size;
    float t_hi = t;
    float h_lo = h_prev;
    float h_hi = h;
    for (int i = 0; i < binary_steps; ++i) {
        float mid = 0.5 * (t_lo + t_hi);
        float h_mid = textureGrad(map, uv + offset * mid, dx, dy).a;
        bool below = 1.0 - mid <= h_mid;
        t_hi = below ? mid : t_hi;
        h_hi = below ? h_mid : h_hi;
        t_lo = below ? t_lo : mid;
        h_lo = below ? h_lo : h_mid;
    }
    // Above the surface at t_lo (d_lo >= 0), at or below it at t_hi
    // (d_hi <= 0); when both are 0 the line has no zero and t_hi stands.
    float d_lo = (1.0 - t_lo) - h_lo;
    float d_hi = (1.0 - t_hi) - h_hi;
    float denom = d_lo - d_hi;
    float t_secant = denom > 0.0 ? t_lo + (t_hi - t_lo) * (d_lo / denom) : t_hi;
    return secant ? t_secant : t_hi;
}
