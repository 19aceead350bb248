// relief_search.cpp: twin of glsl/relief/relief_search.glsl, function for
// function. Inside the linear loop, values the GLSL assigns and then uses
// in the same pass are used as computed (NIR SSA values, unmasked), the
// stores to the loop's variables are masked (shading/control_flow.h).
#include "kernels/relief/relief_search.h"

#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st::relief {

Float trace_height_field(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, const Vec2& dx,
                         const Vec2& dy, int linear_steps, int binary_steps, bool secant) {
    // Every read below has the entry's derivatives, so one level choice
    // serves them all (Sampler2D::grad_levels; the same bits).
    const texel::LevelChoice levels = map.grad_levels(dx, dy);
    const Float size = Float(1.0f) / Float(float(linear_steps));
    Float t = 0.0f;
    Float h = map.sample_grad_alpha(uv, levels);
    Float h_prev = h;
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < Int(linear_steps)));
        exec.assign(h_prev, h);
        const Float t_next = t + size;
        exec.assign(t, t_next);
        const Float h_next = map.sample_grad_alpha(uv + offset * t_next, levels);
        exec.assign(h, h_next);
        loop.break_if(Float(1.0f) - t_next <= h_next);
        exec.assign(i, i + 1);
    });
    Float t_lo = t - size;
    Float t_hi = t;
    Float h_lo = h_prev;
    Float h_hi = h;
    Int k = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(k < Int(binary_steps)));
        const Float mid = Float(0.5f) * (t_lo + t_hi);
        const Float h_mid = map.sample_grad_alpha(uv + offset * mid, levels);
        const Mask below = Float(1.0f) - mid <= h_mid;
        exec.assign(t_hi, glsl::select(below, mid, t_hi));
        exec.assign(h_hi, glsl::select(below, h_mid, h_hi));
        exec.assign(t_lo, glsl::select(below, t_lo, mid));
        exec.assign(h_lo, glsl::select(below, h_lo, h_mid));
        exec.assign(k, k + 1);
    });
    const Float d_lo = (Float(1.0f) - t_lo) - h_lo;
    const Float d_hi = (Float(1.0f) - t_hi) - h_hi;
    const Float denom = d_lo - d_hi;
    const Float t_secant = glsl::select(denom > Float(0.0f), t_lo + (t_hi - t_lo) * (d_lo / denom), t_hi);
    return secant ? t_secant : t_hi;
}

}  // namespace st::relief
