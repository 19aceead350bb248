// thin_slab_model.glsl: single scattering in a thin slab, Frisvad,
// Christensen and Falster, "Efficient Light Scattering through Thin
// Semi-Transparent Objects", Eq. 4-9. Included (#include) by the
// thin_slab* programs; Twin: kernels/thin_slab/thin_slab_model.cpp, function for
// function. Numerically stable where the formulas are not:
// - 1 - exp(-x) for small x (Eq. 4) and the removable singularity of Eq. 5 at
//   mu = mu0 go through series branches (GLSL has no expm1);
// - mu and mu0 are kept >= MU_MIN, so grazing angles give alpha = 0 and a
//   finite radiance instead of 0/0.

const float INV_4PI = 0.0795774715459;  // 1 / (4 pi)
const float INV_PI = 0.318309886184;    // 1 / pi
const float MU_MIN = 1.0e-6;            // below this, cosines count as grazing
const float R2_MIN = 1.0e-12;           // squared light distance floor
const float SERIES_LIMIT = 0.125;       // |x| below which the series are used

// 1 - exp(-x) for x >= 0. Below SERIES_LIMIT the Taylor series to x^5:
// the first omitted term is x^6/720, a relative 4e-8 at the limit.
float one_minus_exp_neg(float x) {
    if (x < SERIES_LIMIT) {
        return x * (1.0 - x * (0.5 - x * (0.16666667 - x * (0.041666668 - x * 0.0083333338))));
    }
    return 1.0 - exp(-x);
}

// (exp(d) - 1) / d, for |d| < SERIES_LIMIT, by its series to d^4.
float expm1_over_x(float d) {
    return 1.0 + d * (0.5 + d * (0.16666667 + d * (0.041666668 + d * 0.0083333338)));
}

// Eq. 4 without E(0) Lambda / (4 pi): mu0 / (mu + mu0) (1 - e^(-tau1 (1/mu + 1/mu0))).
float frontlit_factor(float tau1, float mu, float mu0) {
    float x = tau1 * (mu + mu0) / (mu * mu0);
    return mu0 / (mu + mu0) * one_minus_exp_neg(x);
}

// Eq. 5 without E(0) Lambda / (4 pi): mu0 / (mu - mu0) (e^(-tau1/mu) - e^(-tau1/mu0)).
// With d = tau1 (mu - mu0) / (mu mu0) it equals (tau1/mu) e^(-tau1/mu0) expm1(d)/d,
// which has no singularity at mu = mu0; away from it the direct form is used,
// whose cancellation costs at most about eps / |d|.
float backlit_factor(float tau1, float mu, float mu0) {
    float d = tau1 * (mu - mu0) / (mu * mu0);
    if (abs(d) < SERIES_LIMIT) {
        return tau1 / mu * exp(-tau1 / mu0) * expm1_over_x(d);
    }
    return mu0 / (mu - mu0) * (exp(-tau1 / mu) - exp(-tau1 / mu0));
}

// Eq. 6: irradiance from an isotropic point light of flux `power` at squared
// distance r2, arriving at cosine mu0.
float point_light_irradiance(float power, float mu0, float r2) {
    return power * INV_4PI * mu0 / r2;
}

// The geometry of Eq. 4-8 at surface point p with unit normal n: the squared
// light distance, mu0 towards the light (the normal turned so that mu0 > 0,
// Sec. 4), mu towards the eye, and whether the eye is on the light's side.
struct SlabGeometry {
    float r2;
    float mu0;
    float mu;
    bool frontlit;
};

SlabGeometry slab_geometry(vec3 p, vec3 n, vec3 eye, vec3 light) {
    vec3 to_light = light - p;
    float r2 = max(dot(to_light, to_light), R2_MIN);
    vec3 l = to_light * inversesqrt(r2);
    vec3 w = normalize(eye - p);
    float cos_l = dot(n, l);
    float cos_v = dot(n, w);
    return SlabGeometry(r2, max(abs(cos_l), MU_MIN), max(abs(cos_v), MU_MIN), (cos_l >= 0.0) == (cos_v >= 0.0));
}

// Eq. 7 / 8 with Eq. 4 / 5 and Eq. 6: rgb = the single-scattered radiance
// L_source, a = alpha = e^(-tau1/mu), the direct transmission that Eq. 9's
// blend applies to the destination. Front-lit: Eq. 4; back-lit: Eq. 5.
vec4 thin_slab(vec3 p, vec3 n, vec3 eye, vec3 light, float power, float tau1, vec3 albedo) {
    SlabGeometry g = slab_geometry(p, n, eye, light);
    float factor = g.frontlit ? frontlit_factor(tau1, g.mu, g.mu0) : backlit_factor(tau1, g.mu, g.mu0);
    float radiance = point_light_irradiance(power, g.mu0, g.r2) * INV_4PI * factor;
    float alpha = exp(-tau1 / g.mu);
    return vec4(albedo * radiance, alpha);
}

// The paper's comparison (Figure 2, top row): Lambertian reflection of the
// point light, rgb = albedo E / pi, when the eye is on the light's side and
// black when back-lit; the caller blends it with a constant alpha.
vec3 lambert_baseline(vec3 p, vec3 n, vec3 eye, vec3 light, float power, vec3 albedo) {
    SlabGeometry g = slab_geometry(p, n, eye, light);
    float radiance = g.frontlit ? point_light_irradiance(power, g.mu0, g.r2) * INV_PI : 0.0;
    return albedo * radiance;
}
