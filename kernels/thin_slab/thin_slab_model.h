// thin_slab_model.h: twin of glsl/thin_slab_model.glsl (Frisvad et al.,
// Eq. 4-9), function for function. Also what the host variant evaluates per
// vertex on the CPU, and what the unit tests check against analytic values.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace st {

inline constexpr float INV_4PI = 0.0795774715459f;  // 1 / (4 pi)
inline constexpr float INV_PI = 0.318309886184f;    // 1 / pi
inline constexpr float MU_MIN = 1.0e-6f;
inline constexpr float R2_MIN = 1.0e-12f;
inline constexpr float SERIES_LIMIT = 0.125f;

float one_minus_exp_neg(float x);
float expm1_over_x(float d);
float frontlit_factor(float tau1, float mu, float mu0);   // Eq. 4 bracket
float backlit_factor(float tau1, float mu, float mu0);    // Eq. 5 bracket
float point_light_irradiance(float power, float mu0, float r2);  // Eq. 6
struct SlabGeometry {  // the GLSL struct of the same name
    float r2, mu0, mu;
    bool frontlit;
};
SlabGeometry slab_geometry(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye, const glm::vec3& light);
glm::vec4 thin_slab(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye, const glm::vec3& light,
                    float power, float tau1, const glm::vec3& albedo);  // Eq. 7/8 + alpha (Eq. 9)
glm::vec3 lambert_baseline(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye,
                           const glm::vec3& light, float power, const glm::vec3& albedo);

}  // namespace st
