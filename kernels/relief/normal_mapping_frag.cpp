// normal_mapping_frag.cpp: twin of glsl/relief/normal_mapping.frag, line for
// line.
#include "kernels/relief/relief.h"

#include "kernels/relief/relief_shading.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t NormalMappingFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_uv, "xy"); }

Vec4 NormalMappingFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy();
    const Vec3 p = frag.varying(v_position).xyz();
    // Both reads at uv share its implicit LOD (the maps are one size; a
    // map of another would choose its own).
    const Sampler2D::ImplicitLevels lod = u_.relief_map->implicit_levels(uv);
    const Vec3 n = relief::decode_normal(u_.relief_map->sample(uv, lod));
    const Vec3 albedo = u_.colour_map->sample(uv, lod, texel::kReadRGB).xyz();
    const Vec3 l = glsl::normalize(Vec3(u_.light) - p);
    const Vec3 v = glsl::normalize(Vec3(u_.eye) - p);
    return Vec4(relief::blinn_phong(albedo, n, l, v, Float(u_.ambient), Float(u_.specular)), Float(1.0f));
}

}  // namespace st
