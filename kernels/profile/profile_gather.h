// profile_gather.h: twin of glsl/profile/profile_gather.glsl (the gather
// both gather programs share); definitions in profile_gather.cpp.
#pragma once

#include "kernels/profile/profile.h"

namespace st::profile {

Vec3 blended_profile(Float c, const Vec3& R, const Vec3& T);
Vec3 diffused_light(Exec& exec, const GatherInputs& u, const Vec3& x, const Vec3& n_s, const Vec2& uv, bool thin);
Vec3 surface_reflection(const GatherInputs& u, const Vec3& p, const Vec3& n);

}  // namespace st::profile
