// relief_mapping_frag.cpp: twin of glsl/relief/relief_mapping.frag, line for
// line, and two CPU-only measuring modes the relief sweep uses (app/
// cmd_sweep_relief.cpp; GL never sees them): an intersector in place of the
// search (app/quality/relief_exact.h), and the hit itself as the output (the
// output_hit uniform: hit_uv, t).
#include "kernels/relief/relief.h"

#include "kernels/relief/relief_search.h"
#include "kernels/relief/relief_shading.h"
#include "shading/derivatives.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_uv = 1;  // inputs
}  // namespace

void ReliefMappingFragment::bind(const Bindings& b) {
    u_.read(b);
    depth_ = b.get_float("depth");
    world_depth_ = b.get_float("world_depth");
    linear_steps_ = b.get_int("linear_steps");
    min_linear_steps_ = b.get_int_or("min_linear_steps", 0);
    binary_steps_ = b.get_int("binary_steps");
    secant_ = b.get_int("secant") != 0;
    ulp_perturbation_ = b.get_int_or("ulp_perturbation", 0);
    output_hit_ = b.get_int_or("output_hit", 0) != 0;
    if (exact_) exact_->bind(*u_.relief_map);
}

uint32_t ReliefMappingFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_uv, "xy"); }

Vec4 ReliefMappingFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy();
    const Vec3 p = frag.varying(v_position).xyz();
    const Vec3 v = relief::perturbed(glsl::normalize(Vec3(u_.eye) - p), ulp_perturbation_);
    const Vec2 dx = dFdx(uv);
    const Vec2 dy = dFdy(uv);
    const Vec2 offset = Vec2(-v.x, -v.y) * (Float(depth_) / v.z);
    const Int steps = min_linear_steps_ > 0
                          ? simd::itrunc(Float(float(linear_steps_)) +
                                         (Float(float(min_linear_steps_)) - Float(float(linear_steps_))) * v.z)
                          : Int(linear_steps_);
    Mask crossed;  // always, on the floor
    const Float t = exact_ ? exact_->first_crossing(*u_.relief_map, uv, offset, Float(1.0f), Float(-1.0f),
                                                    Float(1.0f), dx, dy, Mask(false), frag.exec().active(), crossed)
                           : relief::trace_height_field(frag.exec(), *u_.relief_map, uv, offset, dx, dy, steps,
                                                        binary_steps_, secant_);
    const Vec2 hit_uv = uv + offset * t;
    if (output_hit_) return Vec4(hit_uv.x, hit_uv.y, t, Float(1.0f));
    const Vec3 hit = p - v * (t * Float(world_depth_) / v.z);
    const Vec3 n = relief::decode_normal(u_.relief_map->sample_grad(hit_uv, dx, dy));
    const Vec3 albedo = u_.colour_map->sample_grad(hit_uv, dx, dy).xyz();
    const Vec3 l = glsl::normalize(Vec3(u_.light) - hit);
    return Vec4(relief::blinn_phong(albedo, n, l, v, Float(u_.ambient), Float(u_.specular)), Float(1.0f));
}

}  // namespace st
