// thin_slab_model.cpp: twin of glsl/thin_slab_model.glsl, line for line;
// see the GLSL for the derivations. Literals are the GLSL's, as floats.
#include "kernels/thin_slab/thin_slab_model.h"

#include <cmath>

#include "shading/glsl_math.h"

namespace st {

float one_minus_exp_neg(float x) {
    if (x < SERIES_LIMIT) {
        return x * (1.0f - x * (0.5f - x * (0.16666667f - x * (0.041666668f - x * 0.0083333338f))));
    }
    return 1.0f - glsl::exp(-x);
}

float expm1_over_x(float d) {
    return 1.0f + d * (0.5f + d * (0.16666667f + d * (0.041666668f + d * 0.0083333338f)));
}

float frontlit_factor(float tau1, float mu, float mu0) {
    float x = tau1 * (mu + mu0) / (mu * mu0);
    return mu0 / (mu + mu0) * one_minus_exp_neg(x);
}

float backlit_factor(float tau1, float mu, float mu0) {
    float d = tau1 * (mu - mu0) / (mu * mu0);
    if (std::abs(d) < SERIES_LIMIT) {
        return tau1 / mu * glsl::exp(-tau1 / mu0) * expm1_over_x(d);
    }
    return mu0 / (mu - mu0) * (glsl::exp(-tau1 / mu) - glsl::exp(-tau1 / mu0));
}

float point_light_irradiance(float power, float mu0, float r2) {
    return power * INV_4PI * mu0 / r2;
}

SlabGeometry slab_geometry(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye, const glm::vec3& light) {
    glm::vec3 to_light = light - p;
    float r2 = std::fmax(glsl::dot(to_light, to_light), R2_MIN);
    glm::vec3 l = to_light * glsl::inversesqrt(r2);
    glm::vec3 w = glsl::normalize(eye - p);
    float cos_l = glsl::dot(n, l);
    float cos_v = glsl::dot(n, w);
    return SlabGeometry{r2, std::fmax(std::abs(cos_l), MU_MIN), std::fmax(std::abs(cos_v), MU_MIN),
                        (cos_l >= 0.0f) == (cos_v >= 0.0f)};
}

glm::vec4 thin_slab(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye, const glm::vec3& light,
                    float power, float tau1, const glm::vec3& albedo) {
    SlabGeometry g = slab_geometry(p, n, eye, light);
    float factor = g.frontlit ? frontlit_factor(tau1, g.mu, g.mu0) : backlit_factor(tau1, g.mu, g.mu0);
    float radiance = point_light_irradiance(power, g.mu0, g.r2) * INV_4PI * factor;
    float alpha = glsl::exp(-tau1 / g.mu);
    return glm::vec4(albedo * radiance, alpha);
}

glm::vec3 lambert_baseline(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye,
                           const glm::vec3& light, float power, const glm::vec3& albedo) {
    SlabGeometry g = slab_geometry(p, n, eye, light);
    float radiance = g.frontlit ? point_light_irradiance(power, g.mu0, g.r2) * INV_PI : 0.0f;
    return albedo * radiance;
}

}  // namespace st
