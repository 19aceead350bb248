// relief_shading.h: twin of glsl/relief/relief_shading.glsl (the lighting
// every relief row shares); definitions in relief_shading.cpp.
#pragma once

#include "simd/lane_vec.h"

namespace st::relief {

Float highlight32(const Vec3& n, const Vec3& l, const Vec3& v);
Vec3 lit_blinn_phong(const Vec3& albedo, const Vec3& n, const Vec3& l, const Vec3& v, Float ambient, Float specular,
                     const Vec3& light);
Vec3 blinn_phong(const Vec3& albedo, const Vec3& n, const Vec3& l, const Vec3& v, Float ambient, Float specular);
Vec3 decode_normal(const Vec4& texel);
Float fresnel_reflectance(Float n1, Float n2, Float cos_i, Float cos_t);

}  // namespace st::relief
