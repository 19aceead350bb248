// relief_search.cpp: twin of glsl/relief/relief_search.glsl, function for
// function. Inside the linear loop, values the GLSL assigns and then uses
// in the same pass are used as computed (NIR SSA values, unmasked), the
// stores to the loop's variables are masked (shading/control_flow.h).
#include "kernels/relief/relief_search.h"

#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st::relief {

Float trace_segment(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                    Float side, const Vec2& dx, const Vec2& dy, Int linear_steps, int binary_steps, bool secant,
                    Mask& hit) {
    // Every read below has the entry's derivatives, so one level choice
    // serves them all (Sampler2D::grad_levels; the same bits), and only
    // heights are read (sample_grad_alpha).
    const texel::LevelChoice levels = map.grad_levels(dx, dy);
    // One count per lane (scaled by the view angle) or the same on all.
    const Float size = Float(1.0f) / simd::to_float(linear_steps);
    Float s = 0.0f;
    Float h = map.sample_grad_alpha(uv, levels);
    Float h_prev = h;
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < linear_steps));
        exec.assign(h_prev, h);
        const Float s_next = s + size;
        exec.assign(s, s_next);
        const Float h_next = map.sample_grad_alpha(uv + offset * s_next, levels);
        exec.assign(h, h_next);
        loop.break_if(side * (a + dh * s_next) <= side * h_next);
        exec.assign(i, i + 1);
    });
    hit = side * (a + dh * s) <= side * h;
    Float s_lo = s - size;
    Float s_hi = s;
    Float h_lo = h_prev;
    Float h_hi = h;
    Int k = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(k < Int(binary_steps)));
        const Float mid = Float(0.5f) * (s_lo + s_hi);
        const Float h_mid = map.sample_grad_alpha(uv + offset * mid, levels);
        const Mask below = side * (a + dh * mid) <= side * h_mid;
        exec.assign(s_hi, glsl::select(below, mid, s_hi));
        exec.assign(h_hi, glsl::select(below, h_mid, h_hi));
        exec.assign(s_lo, glsl::select(below, s_lo, mid));
        exec.assign(h_lo, glsl::select(below, h_lo, h_mid));
        exec.assign(k, k + 1);
    });
    const Float d_lo = side * ((a + dh * s_lo) - h_lo);
    const Float d_hi = side * ((a + dh * s_hi) - h_hi);
    const Float denom = d_lo - d_hi;
    const Float s_line = s_lo + (s_hi - s_lo) * (d_lo / denom);
    const Float s_secant = glsl::select(denom > Float(0.0f), glsl::min(glsl::max(s_line, s_lo), s_hi), s_hi);
    return glsl::select(Mask(secant) && hit, s_secant, s_hi);
}

Mask segment_blocked(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                     const Vec2& dx, const Vec2& dy, int linear_steps) {
    const texel::LevelChoice levels = map.grad_levels(dx, dy);
    const Float size = Float(1.0f) / Float(float(linear_steps));
    Float s = 0.0f;
    Float h = map.sample_grad_alpha(uv, levels);
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < Int(linear_steps)));
        const Float s_next = s + size;
        exec.assign(s, s_next);
        const Float h_next = map.sample_grad_alpha(uv + offset * s_next, levels);
        exec.assign(h, h_next);
        loop.break_if(a + dh * s_next <= h_next);
        exec.assign(i, i + 1);
    });
    return a + dh * s <= h;
}

Float trace_height_field(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, const Vec2& dx,
                         const Vec2& dy, Int linear_steps, int binary_steps, bool secant) {
    Mask hit;
    return trace_segment(exec, map, uv, offset, Float(1.0f), Float(-1.0f), Float(1.0f), dx, dy, linear_steps,
                         binary_steps, secant, hit);
}

}  // namespace st::relief
