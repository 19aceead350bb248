#version 450 core
// two_layer.frag: Table 1's rows 3 to 5, switched on cumulatively as the
// paper measures them: two-layer translucency (Timonen Algorithm 1), light
// occlusion (Algorithm 2, `occlusion`) and hued absorption (Eq. 1,
// `absorption`); and the light's highlight on the medium with Phong-specular
// intensification (Sec. 3.2), which the rows leave off. Two relief layers with their own boxes below the polygon:
// the solid one (stones, relief_map) and the surface of the translucent
// medium (liquid_map). The view ray meets the nearer of the two; on the
// solid layer the fragment is shaded as in relief mapping; on the medium the
// unpolarised Fresnel terms split it: the refracted ray is traced to the
// solid layer, the reflected ray into the surface, taking the environment
// cube map where it leaves the box. Only the first encounter with the
// medium is followed, as the paper does.
// Twin: kernels/relief/two_layer_frag.cpp.
#include "relief_shading.glsl"
#include "relief_search.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D relief_map;  // the solid layer: rgb normal, a height
uniform sampler2D colour_map;
uniform sampler2D liquid_map;  // the medium's surface: rgb normal, a height
uniform samplerCube environment;
uniform vec3 eye;
uniform vec3 light;
uniform float ambient;
uniform float specular;
uniform float depth;         // the solid layer's box, texture units
uniform float liquid_depth;  // the medium's box, texture units
uniform float world_per_uv;  // world units per texture unit
uniform float ior;           // the medium's index of refraction (outside: 1)
uniform int linear_steps;
uniform int binary_steps;
uniform bool secant;
uniform bool occlusion;      // row 4: the light traced back through the layers
uniform bool absorption;     // row 5: the medium absorbs per channel
uniform int max_crossings;   // medium boundaries a light ray is followed through
uniform float shadow_bias;   // solid-layer heights the light ray starts above its point
uniform vec3 half_distance;  // Eq. 1's d0 per channel, world units
uniform float liquid_specular;  // the light's highlight on the medium (0 in Table 1's rows)
uniform bool intensify;         // Phong-specular intensification (Sec. 3.2)
// Planar local reflections (Sec. 3.2): the refracted and reflected view
// rays meet a flat plane at plane_height (the solid layer's units, 1 at the
// top of its box) instead of being searched.
uniform bool planar;
uniform float plane_height;

// Eq. 1, I = 1 - (1/2)^(d/d0), read as the part of the light the medium
// absorbs over a distance d: the part that survives is (1/2)^(d/d0), so d0
// is the distance over which a channel halves (docs/relief.md).
vec3 surviving(float d) {
    return absorption ? exp2(-d / half_distance) : vec3(1.0);
}

// Algorithm 2: the light reaching a point of the solid layer at uv, z
// texture units below the polygon, from the direction l (towards the
// light). The light ray is followed backwards up to the top of the boxes:
// the solid layer blocks it; each boundary of the medium it passes keeps
// the refracted part 1 - R, its direction unchanged (the paper's footnote
// 4); with absorption the medium also absorbs along the ray's length inside
// it. Crossings are taken past the boundary (no secant step), so that the
// next search starts on the far side.
vec3 light_occlusion(vec2 uv, float z, vec3 l, vec2 dx, vec2 dy) {
    float total = z / max(l.z, 1e-4);  // texture units from the point to the top
    vec2 offset = l.xy * total;
    float a = min(1.0 - z / depth + shadow_bias, 1.0);
    bool blocked = segment_blocked(relief_map, uv, offset, a, 1.0 - a, dx, dy, linear_steps);
    float a_liquid = 1.0 - z / liquid_depth;  // the point's height in the medium's units
    float side = a_liquid < textureGrad(liquid_map, uv, dx, dy).a ? -1.0 : 1.0;  // -1: inside the medium
    float lit = 1.0;
    float inside = 0.0;  // texture units of the ray inside the medium
    float s0 = 0.0;
    for (int i = 0; i < max_crossings; ++i) {
        // z / liquid_depth is 1 - a_liquid as NIR computes it: it rewrites
        // 1 - (1 - x) as x (docs/llvmpipe/nir-algebraic.md), so the shader
        // says x and the twin computes the same.
        float start = a_liquid + (z / liquid_depth) * s0;
        bool crossed;
        float s = trace_segment(liquid_map, uv + offset * s0, offset * (1.0 - s0), start, 1.0 - start, side, dx,
                                dy, linear_steps, binary_steps, false, crossed);
        if (!crossed) break;
        // The step as its own value: NIR rewrites (s0 + d) - s0 as d (an
        // inexact-float rule, docs/llvmpipe/nir-algebraic.md), so the shader
        // says d itself and both sides compute the same.
        float step = (1.0 - s0) * s;
        float s_at = s0 + step;
        vec3 n = decode_normal(textureGrad(liquid_map, uv + offset * s_at, dx, dy));
        // The light passes this boundary on its way down: into the medium
        // where the backward ray leaves it.
        float n1 = side < 0.0 ? 1.0 : ior;
        float n2 = side < 0.0 ? ior : 1.0;
        float cos_i = abs(dot(n, l));
        float sin_t2 = (n1 / n2) * (n1 / n2) * (1.0 - cos_i * cos_i);
        float r = sin_t2 >= 1.0 ? 1.0 : fresnel_reflectance(n1, n2, cos_i, sqrt(1.0 - sin_t2));
        lit = lit * (1.0 - r);
        inside = side < 0.0 ? inside + step * total : inside;
        side = -side;
        s0 = s_at;
    }
    inside = side < 0.0 ? inside + (1.0 - s0) * total : inside;
    vec3 survived = surviving(inside * world_per_uv);
    return blocked || l.z <= 0.0 ? vec3(0.0) : lit * survived;
}

// The solid layer at a hit z texture units deep: its normal and colour
// there, lit from the light (through the layers with `occlusion`), seen
// along to_viewer.
vec3 shade_solid(vec2 uv, vec3 pos, float z, vec3 to_viewer, vec2 dx, vec2 dy) {
    vec3 n = decode_normal(textureGrad(relief_map, uv, dx, dy));
    vec3 albedo = textureGrad(colour_map, uv, dx, dy).rgb;
    vec3 l = normalize(light - pos);
    vec3 lit = occlusion ? light_occlusion(uv, z, l, dx, dy) : vec3(1.0);
    return lit_blinn_phong(albedo, n, l, to_viewer, ambient, specular, lit);
}

void main() {
    vec2 uv = v_uv.xy;
    vec3 p = v_position.xyz;
    vec3 v = normalize(eye - p);  // tangent space = world space; v.z > 0
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    // The view ray through both boxes, each from its top to its floor;
    // z is the depth below the polygon, in texture units.
    float t_solid = trace_height_field(relief_map, uv, -v.xy * (depth / v.z), dx, dy, linear_steps, binary_steps,
                                       secant);
    float t_liquid = trace_height_field(liquid_map, uv, -v.xy * (liquid_depth / v.z), dx, dy, linear_steps,
                                        binary_steps, secant);
    float z_solid = t_solid * depth;
    float z_liquid = t_liquid * liquid_depth;
    vec3 colour;
    if (z_solid <= z_liquid) {
        colour = shade_solid(uv - v.xy * (z_solid / v.z), p - v * (z_solid * world_per_uv / v.z), z_solid, v, dx,
                             dy);
    } else {
        vec2 at_uv = uv - v.xy * (z_liquid / v.z);
        vec3 at = p - v * (z_liquid * world_per_uv / v.z);
        vec3 n = decode_normal(textureGrad(liquid_map, at_uv, dx, dy));
        vec3 refracted = refract(-v, n, 1.0 / ior);
        vec3 reflected = reflect(-v, n);
        float cos_i = max(dot(n, v), 0.0);
        float cos_t = max(-dot(n, refracted), 0.0);
        // Total internal reflection (refract's zero vector) reflects all.
        float r = dot(refracted, refracted) == 0.0 ? 1.0 : fresnel_reflectance(1.0, ior, cos_i, cos_t);
        // The hit's height in the solid layer's units (1 at the top).
        float a = 1.0 - z_liquid / depth;
        bool hit;
        // Refraction: down to the solid layer's floor, which stops it.
        float down = (depth - z_liquid) / max(-refracted.z, 1e-4);
        vec2 down_offset = refracted.xy * down;
        float s;
        if (planar) {
            // Falling from a to 0 along the segment: the plane at s = (a - h) / a,
            // or at once where the ray starts below it.
            s = a > plane_height ? (a - plane_height) / a : 0.0;
        } else {
            s = trace_segment(relief_map, at_uv, down_offset, a, -a, 1.0, dx, dy, linear_steps, binary_steps, secant,
                              hit);
        }
        float refracted_length = s * down;  // texture units, all of it taken as inside the medium
        vec3 refraction = shade_solid(at_uv + down_offset * s, at + refracted * (refracted_length * world_per_uv),
                                      z_liquid + (depth - z_liquid) * s, -refracted, dx, dy) *
                          surviving(refracted_length * world_per_uv);
        // Reflection: up to the top of the box, meeting the solid layer on
        // the way or leaving for the environment.
        float up = z_liquid / max(reflected.z, 1e-4);
        vec2 up_offset = reflected.xy * up;
        float s_up;
        if (planar) {
            // Rising from a to 1: the plane from below where the ray starts
            // under it, else the environment.
            hit = a < plane_height;
            // 1 - a as NIR computes it (see the searched rise below).
            s_up = hit ? (plane_height - a) / (z_liquid / depth) : 1.0;
        } else {
            // The rise to the top, 1 - a, written as NIR computes it
            // (1 - (1 - x) is x; docs/llvmpipe/nir-algebraic.md).
            s_up = trace_segment(relief_map, at_uv, up_offset, a, z_liquid / depth, 1.0, dx, dy, linear_steps,
                                 binary_steps, secant, hit);
        }
        vec3 local = shade_solid(at_uv + up_offset * s_up, at + reflected * (s_up * up * world_per_uv),
                                 z_liquid - z_liquid * s_up, -reflected, dx, dy);
        vec3 reflection = hit ? local : textureLod(environment, reflected, 0.0).rgb;
        // The light's own reflection on the medium: weighted by r with the
        // rest of the reflection it keeps only a few per cent of its peak;
        // intensification divides that weight out again (Sec. 3.2).
        float highlight = liquid_specular * highlight32(n, normalize(light - at), v);
        float gain = intensify ? 1.0 / max(r, 1e-3) : 1.0;
        reflection = reflection + vec3(highlight * gain);
        colour = (1.0 - r) * refraction + r * reflection;
    }
    frag_colour = vec4(colour, 1.0);
}
