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
    ulp_perturbation_ = b.get_int_or("ulp_perturbation", 0);
    planar_ = b.get_int("planar") != 0;
    plane_height_ = b.get_float("plane_height");
    occlusion_ = b.get_int("occlusion") != 0;
    absorption_ = b.get_int("absorption") != 0;
    max_crossings_ = b.get_int("max_crossings");
    shadow_bias_ = b.get_float("shadow_bias");
    half_distance_ = b.get_vec3("half_distance");
    liquid_specular_ = b.get_float("liquid_specular");
    intensify_ = b.get_int("intensify") != 0;
    if (exact_) {
        exact_->bind(*u_.relief_map);
        exact_->bind(*liquid_map_);
    }
}

Float TwoLayerFragment::trace(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                              Float side, const Vec2& dx, const Vec2& dy, bool secant, Mask& hit, Mask leaving) const {
    if (exact_) return exact_->first_crossing(map, uv, offset, a, dh, side, dx, dy, leaving, exec.active(), hit);
    return relief::trace_segment(exec, map, uv, offset, a, dh, side, dx, dy, linear_steps_, binary_steps_, secant, hit);
}

uint32_t TwoLayerFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_uv, "xy"); }

Vec3 TwoLayerFragment::surviving(Float d) const {
    if (!absorption_) return Vec3(Float(1.0f));  // a uniform: one side for every lane
    const Vec3 x = Vec3(-d) / Vec3(half_distance_);
    return Vec3(glsl::exp2(x.x), glsl::exp2(x.y), glsl::exp2(x.z));
}

Vec3 TwoLayerFragment::light_occlusion(Exec& exec, const Vec2& uv, Float z, const Vec3& l, const Vec2& dx,
                                       const Vec2& dy) const {
    const Float total = z / glsl::max(l.z, Float(1e-4f));
    const Vec2 offset = Vec2(l.x, l.y) * total;
    const Float a = glsl::min(Float(1.0f) - z / Float(depth_) + Float(shadow_bias_), Float(1.0f));
    Mask blocked;
    if (exact_)  // from the hit, which segment_blocked never tests (s = 0): leaving it
        trace(exec, *u_.relief_map, uv, offset, a, Float(1.0f) - a, Float(1.0f), dx, dy, false, blocked, Mask(true));
    else
        blocked = relief::segment_blocked(exec, *u_.relief_map, uv, offset, a, Float(1.0f) - a, dx, dy, linear_steps_);
    const Float a_liquid = Float(1.0f) - z / Float(liquid_depth_);
    Float side = glsl::select(a_liquid < liquid_map_->sample_grad(uv, dx, dy).w, Float(-1.0f), Float(1.0f));
    Float lit = 1.0f;
    Float inside = 0.0f;
    Float s0 = 0.0f;
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < Int(max_crossings_)));
        // 1 - a_liquid as NIR computes it (the GLSL says why).
        const Float start = a_liquid + (z / Float(liquid_depth_)) * s0;
        Mask crossed;
        const Float s = trace(exec, *liquid_map_, uv + offset * s0, offset * (Float(1.0f) - s0), start,
                              Float(1.0f) - start, side, dx, dy, false, crossed, i > Int(0));
        loop.break_if(!crossed);
        const Float step = (Float(1.0f) - s0) * s;
        const Float s_at = s0 + step;
        const Vec3 n = relief::decode_normal(liquid_map_->sample_grad(uv + offset * s_at, dx, dy));
        const Mask entering = side < Float(0.0f);
        const Float n1 = glsl::select(entering, Float(1.0f), Float(ior_));
        const Float n2 = glsl::select(entering, Float(ior_), Float(1.0f));
        const Float cos_i = glsl::abs(glsl::dot(n, l));
        const Float sin_t2 = (n1 / n2) * (n1 / n2) * (Float(1.0f) - cos_i * cos_i);
        const Float r = glsl::select(sin_t2 >= Float(1.0f), Float(1.0f),
                                     relief::fresnel_reflectance(n1, n2, cos_i, simd::sqrt(Float(1.0f) - sin_t2)));
        exec.assign(lit, lit * (Float(1.0f) - r));
        exec.assign(inside, glsl::select(entering, inside + step * total, inside));
        exec.assign(side, -side);
        exec.assign(s0, s_at);
        exec.assign(i, i + 1);
    });
    inside = glsl::select(side < Float(0.0f), inside + (Float(1.0f) - s0) * total, inside);
    const Vec3 survived = surviving(inside * Float(world_per_uv_));
    return glsl::select(blocked || l.z <= Float(0.0f), Vec3(Float(0.0f)), Vec3(lit) * survived);
}

Vec3 TwoLayerFragment::shade_solid(Exec& exec, const Vec2& uv, const Vec3& pos, Float z, const Vec3& to_viewer,
                                   const Vec2& dx, const Vec2& dy) const {
    const Vec3 n = relief::decode_normal(u_.relief_map->sample_grad(uv, dx, dy));
    const Vec3 albedo = u_.colour_map->sample_grad(uv, dx, dy).xyz();
    const Vec3 l = glsl::normalize(Vec3(u_.light) - pos);
    const Vec3 lit = occlusion_ ? light_occlusion(exec, uv, z, l, dx, dy) : Vec3(Float(1.0f));
    return relief::lit_blinn_phong(albedo, n, l, to_viewer, Float(u_.ambient), Float(u_.specular), lit);
}

Vec4 TwoLayerFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec2 uv = frag.varying(v_uv).xy();
    const Vec3 p = frag.varying(v_position).xyz();
    const Vec3 v = relief::perturbed(glsl::normalize(Vec3(u_.eye) - p), ulp_perturbation_);
    const Vec2 dx = dFdx(uv);
    const Vec2 dy = dFdy(uv);
    const Vec2 minus_v_xy(-v.x, -v.y);
    // trace_height_field: a = 1, dh = -1, side +1.
    Mask solid_hit, liquid_hit;
    const Float t_solid = trace(exec, *u_.relief_map, uv, minus_v_xy * (Float(depth_) / v.z), Float(1.0f),
                                Float(-1.0f), Float(1.0f), dx, dy, secant_, solid_hit);
    const Float t_liquid = trace(exec, *liquid_map_, uv, minus_v_xy * (Float(liquid_depth_) / v.z), Float(1.0f),
                                 Float(-1.0f), Float(1.0f), dx, dy, secant_, liquid_hit);
    const Float z_solid = t_solid * Float(depth_);
    const Float z_liquid = t_liquid * Float(liquid_depth_);
    const Vec2 v_xy(v.x, v.y);
    Vec3 colour(Float(0.0f));
    exec.if_else(
        z_solid <= z_liquid,
        [&] {
            exec.assign(colour, shade_solid(exec, uv - v_xy * (z_solid / v.z),
                                            p - v * (z_solid * Float(world_per_uv_) / v.z), z_solid, v, dx, dy));
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
            // A uniform branch: the same value on every lane, as the GLSL's if.
            const Float plane(plane_height_);
            const Float s = planar_ ? glsl::select(a > plane, (a - plane) / a, Float(0.0f))
                                    : trace(exec, *u_.relief_map, at_uv, down_offset, a, -a, Float(1.0f), dx, dy,
                                            secant_, hit);
            const Float refracted_length = s * down;
            const Vec3 refraction =
                shade_solid(exec, at_uv + down_offset * s, at + refracted * (refracted_length * Float(world_per_uv_)),
                            z_liquid + (Float(depth_) - z_liquid) * s, Vec3(-refracted.x, -refracted.y, -refracted.z),
                            dx, dy) *
                surviving(refracted_length * Float(world_per_uv_));
            const Float up = z_liquid / glsl::max(reflected.z, Float(1e-4f));
            const Vec2 up_offset = Vec2(reflected.x, reflected.y) * up;
            Float s_up;
            if (planar_) {
                hit = a < plane;
                s_up = glsl::select(hit, (plane - a) / (z_liquid / Float(depth_)), Float(1.0f));
            } else {
                s_up = trace(exec, *u_.relief_map, at_uv, up_offset, a, z_liquid / Float(depth_), Float(1.0f), dx, dy,
                             secant_, hit);
            }
            const Vec3 local = shade_solid(exec, at_uv + up_offset * s_up,
                                           at + reflected * (s_up * up * Float(world_per_uv_)), z_liquid - z_liquid * s_up,
                                           Vec3(-reflected.x, -reflected.y, -reflected.z), dx, dy);
            Vec3 reflection = glsl::select(hit, local, environment_->sample_lod(reflected, Float(0.0f)).xyz());
            const Float highlight =
                Float(liquid_specular_) * relief::highlight32(n, glsl::normalize(Vec3(u_.light) - at), v);
            const Float gain = intensify_ ? Float(1.0f) / glsl::max(r, Float(1e-3f)) : Float(1.0f);
            reflection = reflection + Vec3(highlight * gain);
            exec.assign(colour, (Float(1.0f) - r) * refraction + r * reflection);
        });
    return Vec4(colour, Float(1.0f));
}

}  // namespace st
