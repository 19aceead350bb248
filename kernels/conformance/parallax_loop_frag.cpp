// parallax_loop_frag.cpp: twin of glsl/conformance/parallax_loop.frag, line
// for line. The loop is a masked loop (shading/control_flow.h): a lane that
// has left keeps its uv, and texture() still takes each quad's LOD from all
// four lanes' coordinates, as llvmpipe does.
#include "kernels/conformance/conformance.h"

#include "shading/glsl_math.h"
#include "shading/glsl_texture.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void ParallaxLoopFragment::bind(const Bindings& b) {
    depth_map_ = &b.sampler("depth_map");
    colour_map_ = &b.sampler("colour_map");
    height_scale_ = b.get_float("height_scale");
    light_dir_ = b.get_vec3("light_dir");
}

uint32_t ParallaxLoopFragment::inputs_read() const { return reads(v_colour, "xyz") | reads(v_uv, "xy"); }

Vec4 ParallaxLoopFragment::main(const Fragment& frag) const {
    using namespace glsl;
    Exec& exec = frag.exec();
    const Vec3 view = normalize(frag.varying(v_colour).xyz());
    // More layers where the ray runs along the surface.
    const Float layers = mix(Float(32.0f), Float(8.0f), abs(view.z));
    const Float layer_depth = 1.0f / layers;
    const Vec2 step_uv = view.xy() / view.z * Float(height_scale_) / layers;

    Vec2 uv = frag.varying(v_uv).xy();
    Float depth = 0.0f;
    // texture(depth_map, uv).r: the sampler filters red alone (kReadR), as
    // the compiler drops the channels a shader never reads.
    Float map_depth = depth_map_->sample(uv, texel::kReadR).x;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(depth < map_depth));
        exec.assign(uv, uv - step_uv);
        // Only the lanes still in the loop use this read (exec's).
        exec.assign(map_depth, texture(*depth_map_, uv, exec, texel::kReadR).x);
        exec.assign(depth, depth + layer_depth);
    });
    // The crossing between the last two layers.
    const Vec2 before_uv = uv + step_uv;
    const Float after = map_depth - depth;
    const Float before = depth_map_->sample(before_uv, texel::kReadR).x - depth + layer_depth;
    const Float w = after / (after - before);
    uv = before_uv * w + uv * (1.0f - w);

    const Vec3 albedo = colour_map_->sample(uv, texel::kReadRGB).xyz();
    const Float lambert = max(Float(light_dir_.z), Float(0.0f));
    return Vec4(albedo * (0.15f + lambert), 1.0f);
}

}  // namespace st
