// profile_optics.h: twin of glsl/profile/profile_optics.glsl (the boundary
// the irradiance and gather passes share); definitions in profile_optics.cpp.
#pragma once

#include "simd/lane_vec.h"

namespace st {
class Sampler2D;
}

namespace st::profile {

Float fresnel_reflectance(Float eta, Float cos_i, Float cos_t);
Float transmittance_in(Float cos_i, Float eta, bool rough, const Sampler2D& rho_dt);

}  // namespace st::profile
