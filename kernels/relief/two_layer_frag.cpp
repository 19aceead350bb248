// two_layer_frag.cpp: twin of glsl/relief/two_layer.frag, line for line.
#include "kernels/relief/relief.h"

#include "kernels/relief/relief_search.h"
#include "kernels/relief/relief_shading.h"
#include "shading/derivatives.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"
#include "texture/sampler_cube.h"

namespace st {

namespace {
constexpr int v_position = 0, v_uv = 1;  // inputs
}  // namespace

void TwoLayerFragment::bind(const Bindings& b) {
    u_.read(b);
    liquid_map_ = &b.sampler("liquid_map");
    environment_ = &b.sampler_cube("environment");
    depth_ = b.get_float("depth");
    liquid_depth_ = b.get_float("liquid_depth");
    world_per_uv_ = b.get_float("world_per_uv");
    ior_ = b.get_float("ior");
    linear_steps_ = b.get_int("linear_steps");
    binary_steps_ = b.get_int("binary_steps");
    secant_ = b.get_int("secant") != 0;
}

uint32_t TwoLayerFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_uv, "xy"); }

Vec3 TwoLayerFragment::shade_solid(const Vec2& uv, const Vec3& pos, const Vec3& to_viewer, const Vec2& dx,
                                   const Vec2& dy) const {
    const Vec3 n = relief::decode_normal(u_.relief_map->sample_grad(uv, dx, dy));
    const Vec3 albedo = u_.colour_map->sample_grad(uv, dx, dy).xyz();
    return relief::blinn_phong(albedo, n, glsl::normalize(Vec3(u_.light) - pos), to_viewer, Float(u_.ambient),
                               Float(u_.specular));
}

Vec4 TwoLayerFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec2 uv = frag.varying(v_uv).xy();
    const Vec3 p = frag.varying(v_position).xyz();
    const Vec3 v = glsl::normalize(Vec3(u_.eye) - p);
    const Vec2 dx = dFdx(uv);
    const Vec2 dy = dFdy(uv);
    const Vec2 minus_v_xy(-v.x, -v.y);
    const Float t_solid = relief::trace_height_field(exec, *u_.relief_map, uv, minus_v_xy * (Float(depth_) / v.z),
                                                     dx, dy, linear_steps_, binary_steps_, secant_);
    const Float t_liquid = relief::trace_height_field(exec, *liquid_map_, uv,
                                                      minus_v_xy * (Float(liquid_depth_) / v.z), dx, dy,
                                                      linear_steps_, binary_steps_, secant_);
    const Float z_solid = t_solid * Float(depth_);
    const Float z_liquid = t_liquid * Float(liquid_depth_);
    const Vec2 v_xy(v.x, v.y);
    Vec3 colour(Float(0.0f));
    exec.if_else(
        z_solid <= z_liquid,
        [&] {
            exec.assign(colour, shade_solid(uv - v_xy * (z_solid / v.z),
                                            p - v * (z_solid * Float(world_per_uv_) / v.z), v, dx, dy));
        },
        [&] {
            const Vec2 at_uv = uv - v_xy * (z_liquid / v.z);
            const Vec3 at = p - v * (z_liquid * Float(world_per_uv_) / v.z);
            const Vec3 n = relief::decode_normal(liquid_map_->sample_grad(at_uv, dx, dy));
            const Vec3 minus_v(-v.x, -v.y, -v.z);
            const Vec3 refracted = glsl::refract(minus_v, n, Float(1.0f) / Float(ior_));
            const Vec3 reflected = glsl::reflect(minus_v, n);
            const Float cos_i = glsl::max(glsl::dot(n, v), Float(0.0f));
            const Float cos_t = glsl::max(-glsl::dot(n, refracted), Float(0.0f));
            const Float r = glsl::select(glsl::dot(refracted, refracted) == Float(0.0f), Float(1.0f),
                                         relief::fresnel_reflectance(Float(1.0f), Float(ior_), cos_i, cos_t));
            const Float a = Float(1.0f) - z_liquid / Float(depth_);
            Mask hit;
            const Float down = (Float(depth_) - z_liquid) / glsl::max(-refracted.z, Float(1e-4f));
            const Vec2 down_offset = Vec2(refracted.x, refracted.y) * down;
            const Float s = relief::trace_segment(exec, *u_.relief_map, at_uv, down_offset, a, -a, Float(1.0f), dx,
                                                  dy, linear_steps_, binary_steps_, secant_, hit);
            const Vec3 refraction = shade_solid(at_uv + down_offset * s,
                                                at + refracted * (s * down * Float(world_per_uv_)),
                                                Vec3(-refracted.x, -refracted.y, -refracted.z), dx, dy);
            const Float up = z_liquid / glsl::max(reflected.z, Float(1e-4f));
            const Vec2 up_offset = Vec2(reflected.x, reflected.y) * up;
            const Float s_up = relief::trace_segment(exec, *u_.relief_map, at_uv, up_offset, a, Float(1.0f) - a, Float(1.0f), dx,
                                                     dy, linear_steps_, binary_steps_, secant_, hit);
            const Vec3 local = shade_solid(at_uv + up_offset * s_up, at + reflected * (s_up * up * Float(world_per_uv_)),
                                           Vec3(-reflected.x, -reflected.y, -reflected.z), dx, dy);
            const Vec3 reflection = glsl::select(hit, local, environment_->sample_lod(reflected, Float(0.0f)).xyz());
            exec.assign(colour, (Float(1.0f) - r) * refraction + r * reflection);
        });
    return Vec4(colour, Float(1.0f));
}

}  // namespace st
