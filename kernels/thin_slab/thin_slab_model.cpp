// thin_slab_model.cpp: twin of glsl/thin_slab/thin_slab_model.glsl, line for
// line; see the GLSL for the derivations. Literals are the GLSL's, as
// floats. An `if` that returns on each side, and a ternary with costly
// sides, is glsl::if_else here: each lane takes its side, and a side no lane
// takes is skipped; the result is select()'s for every lane.
#include "kernels/thin_slab/thin_slab_model.h"

#include "shading/glsl_math.h"

namespace st {

template <class F>
F one_minus_exp_neg(F x) {
    return glsl::if_else(
        x < F(SERIES_LIMIT),
        [&] { return x * (F(1.0f) - x * (F(0.5f) - x * (F(0.16666667f) - x * (F(0.041666668f) - x * F(0.0083333338f))))); },
        [&] { return F(1.0f) - glsl::exp(-x); });
}

template <class F>
F expm1_over_x(F d) {
    return F(1.0f) + d * (F(0.5f) + d * (F(0.16666667f) + d * (F(0.041666668f) + d * F(0.0083333338f))));
}

template <class F>
F frontlit_factor(F tau1, F mu, F mu0) {
    F x = tau1 * (mu + mu0) / (mu * mu0);
    return mu0 / (mu + mu0) * one_minus_exp_neg(x);
}

template <class F>
F backlit_factor(F tau1, F mu, F mu0) {
    F d = tau1 * (mu - mu0) / (mu * mu0);
    return glsl::if_else(
        glsl::abs(d) < F(SERIES_LIMIT), [&] { return tau1 / mu * glsl::exp(-tau1 / mu0) * expm1_over_x(d); },
        [&] { return mu0 / (mu - mu0) * (glsl::exp(-tau1 / mu) - glsl::exp(-tau1 / mu0)); });
}

template <class F>
F point_light_irradiance(F power, F mu0, F r2) {
    return power * F(INV_4PI) * mu0 / r2;
}

template <class F>
SlabGeometry<F> slab_geometry(const Vec3Of<F>& p, const Vec3Of<F>& n, const Vec3Of<F>& eye, const Vec3Of<F>& light) {
    Vec3Of<F> to_light = light - p;
    F r2 = glsl::max(glsl::dot(to_light, to_light), F(R2_MIN));
    Vec3Of<F> l = to_light * glsl::inversesqrt(r2);
    Vec3Of<F> w = glsl::normalize(eye - p);
    F cos_l = glsl::dot(n, l);
    F cos_v = glsl::dot(n, w);
    return SlabGeometry<F>{r2, glsl::max(glsl::abs(cos_l), F(MU_MIN)), glsl::max(glsl::abs(cos_v), F(MU_MIN)),
                           (cos_l >= F(0.0f)) == (cos_v >= F(0.0f))};
}

template <class F>
Vec4Of<F> thin_slab(const Vec3Of<F>& p, const Vec3Of<F>& n, const Vec3Of<F>& eye, const Vec3Of<F>& light, F power,
                    F tau1, const Vec3Of<F>& albedo) {
    SlabGeometry<F> g = slab_geometry<F>(p, n, eye, light);
    F factor = glsl::if_else(
        g.frontlit, [&] { return frontlit_factor(tau1, g.mu, g.mu0); }, [&] { return backlit_factor(tau1, g.mu, g.mu0); });
    F radiance = point_light_irradiance(power, g.mu0, g.r2) * F(INV_4PI) * factor;
    F alpha = glsl::exp(-tau1 / g.mu);
    return Vec4Of<F>(albedo * radiance, alpha);
}

template <class F>
Vec3Of<F> lambert_baseline(const Vec3Of<F>& p, const Vec3Of<F>& n, const Vec3Of<F>& eye, const Vec3Of<F>& light,
                           F power, const Vec3Of<F>& albedo) {
    SlabGeometry<F> g = slab_geometry<F>(p, n, eye, light);
    F radiance = glsl::select(g.frontlit, point_light_irradiance(power, g.mu0, g.r2) * F(INV_PI), F(0.0f));
    return albedo * radiance;
}

// Both number types, for every function above.
#define ST_THIN_SLAB_MODEL(F)                                                                            \
    template F one_minus_exp_neg<F>(F);                                                                  \
    template F expm1_over_x<F>(F);                                                                       \
    template F frontlit_factor<F>(F, F, F);                                                              \
    template F backlit_factor<F>(F, F, F);                                                               \
    template F point_light_irradiance<F>(F, F, F);                                                       \
    template SlabGeometry<F> slab_geometry<F>(const Vec3Of<F>&, const Vec3Of<F>&, const Vec3Of<F>&,      \
                                              const Vec3Of<F>&);                                         \
    template Vec4Of<F> thin_slab<F>(const Vec3Of<F>&, const Vec3Of<F>&, const Vec3Of<F>&, const Vec3Of<F>&, \
                                    F, F, const Vec3Of<F>&);                                             \
    template Vec3Of<F> lambert_baseline<F>(const Vec3Of<F>&, const Vec3Of<F>&, const Vec3Of<F>&,        \
                                           const Vec3Of<F>&, F, const Vec3Of<F>&);
ST_THIN_SLAB_MODEL(float)
ST_THIN_SLAB_MODEL(Float)
#undef ST_THIN_SLAB_MODEL

}  // namespace st
