// profile_optics.h: twin of glsl/profile/profile_optics.glsl (the boundary
// the irradiance and gather passes share); definitions in profile_optics.cpp.
#pragma once

#include <glm/vec4.hpp>

#include "simd/lane_vec.h"

namespace st {
class Sampler2D;
}

namespace st::profile {

Float fresnel_reflectance(Float eta, Float cos_i, Float cos_t);
Float transmittance_in(Float cos_i, Float eta, bool rough, const Sampler2D& rho_dt);
Float coverage(Float s);
Float light_pattern(const Vec2& p, const glm::vec4& spot, const glm::vec4& edge);
Float torrance_sparrow(const Vec3& n, const Vec3& l, const Vec3& v, Float eta, Float inv_m2, Float beckmann_norm);

}  // namespace st::profile
