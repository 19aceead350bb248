// thin_slab_model.h: twin of glsl/thin_slab/thin_slab_model.glsl (Frisvad et
// al., Eq. 4-9), function for function. Each function is written once for
// F = float (the vertex variant, the host variant's per-vertex evaluation,
// the unit tests) and F = Float (the fragment twins, all lanes at once);
// thin_slab_model.cpp instantiates both.
#pragma once

#include "simd/lane_vec.h"

namespace st {

inline constexpr float INV_4PI = 0.0795774715459f;  // 1 / (4 pi)
inline constexpr float INV_PI = 0.318309886184f;    // 1 / pi
inline constexpr float MU_MIN = 1.0e-6f;
inline constexpr float R2_MIN = 1.0e-12f;
inline constexpr float SERIES_LIMIT = 0.125f;

template <class F> F one_minus_exp_neg(F x);
template <class F> F expm1_over_x(F d);
template <class F> F frontlit_factor(F tau1, F mu, F mu0);   // Eq. 4 bracket
template <class F> F backlit_factor(F tau1, F mu, F mu0);    // Eq. 5 bracket
template <class F> F point_light_irradiance(F power, F mu0, F r2);  // Eq. 6
template <class F> struct SlabGeometry {  // the GLSL struct of the same name
    F r2, mu0, mu;
    BoolOf<F> frontlit;
};
template <class F>
SlabGeometry<F> slab_geometry(const Vec3Of<F>& p, const Vec3Of<F>& n, const Vec3Of<F>& eye, const Vec3Of<F>& light);
template <class F>  // Eq. 7/8 + alpha (Eq. 9)
Vec4Of<F> thin_slab(const Vec3Of<F>& p, const Vec3Of<F>& n, const Vec3Of<F>& eye, const Vec3Of<F>& light,
                    F power, F tau1, const Vec3Of<F>& albedo);
template <class F>
Vec3Of<F> lambert_baseline(const Vec3Of<F>& p, const Vec3Of<F>& n, const Vec3Of<F>& eye, const Vec3Of<F>& light,
                           F power, const Vec3Of<F>& albedo);

}  // namespace st
