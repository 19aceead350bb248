#version 450 core
// parallax_loop.frag: the benchmark of the path a user's shader takes (issue
// 30): parallax occlusion mapping as tutorials write it. The view ray
// marches into the depth map in layers, one implicit-LOD texture() a layer
// inside a while loop that each lane leaves at its own step (a quad's
// derivatives then come from lanes that stopped moving), then the colour map
// is read at the interpolated crossing. Trilinear RGBA8 maps.
// Twin: kernels/conformance/parallax_loop_frag.cpp.
layout(location = 0) in vec4 v_colour;  // xyz: the vector to the eye, tangent space
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D depth_map;   // depth below the top in red (0 = top)
uniform sampler2D colour_map;
uniform float height_scale;    // texture units of depth at depth 1
uniform vec3 light_dir;        // towards the light, tangent space, unit

void main() {
    vec3 view = normalize(v_colour.xyz);
    // More layers where the ray runs along the surface.
    float layers = mix(32.0, 8.0, abs(view.z));
    float layer_depth = 1.0 / layers;
    vec2 step_uv = view.xy / view.z * height_scale / layers;

    vec2 uv = v_uv.xy;
    float depth = 0.0;
    float map_depth = texture(depth_map, uv).r;
    while (depth < map_depth) {
        uv -= step_uv;
        map_depth = texture(depth_map, uv).r;
        depth += layer_depth;
    }
    // The crossing between the last two layers, where the straight lines of
    // ray and map depth meet.
    vec2 before_uv = uv + step_uv;
    float after = map_depth - depth;
    float before = texture(depth_map, before_uv).r - depth + layer_depth;
    float w = after / (after - before);
    uv = before_uv * w + uv * (1.0 - w);

    vec3 albedo = texture(colour_map, uv).rgb;
    float lambert = max(light_dir.z, 0.0);
    frag_colour = vec4(albedo * (0.15 + lambert), 1.0);
}
