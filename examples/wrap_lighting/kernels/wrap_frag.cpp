// wrap_frag.cpp: twin of glsl/wrap.frag, line for line, on all lanes at once.
#include "wrap.h"

#include "shading/glsl_math.h"

namespace {
constexpr int v_normal = 0;  // inputs
}  // namespace

void WrapFragment::bind(const st::Bindings& b) {
    light_dir_ = b.get_vec3("light_dir");
    albedo_ = b.get_vec3("albedo");
    scatter_tint_ = b.get_vec3("scatter_tint");
    wrap_ = b.get_float("wrap");
}

uint32_t WrapFragment::inputs_read() const { return st::reads(v_normal, "xyz"); }

st::Vec4 WrapFragment::main(const st::Fragment& frag) const {
    using st::Float, st::Vec3;
    namespace glsl = st::glsl;
    const Vec3 n = glsl::normalize(frag.varying(v_normal).xyz());
    const Float n_dot_l = glsl::dot(n, Vec3(light_dir_));
    const Float lambert = glsl::max(n_dot_l, Float(0.0f));
    const Float wrapped = glsl::max((n_dot_l + Float(wrap_)) / (Float(1.0f) + Float(wrap_)), Float(0.0f));
    const Vec3 colour = Vec3(albedo_) * lambert + Vec3(scatter_tint_) * (wrapped - lambert);
    return st::Vec4(colour, Float(1.0f));
}
