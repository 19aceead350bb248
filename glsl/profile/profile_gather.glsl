// profile_gather.glsl: the gather of diffusion-profile rendering (Donner and
// Jensen Sec. 3): the light leaving a visible point x is the irradiance
// entering the surface around it weighted by the material's profile,
// M(x) = sum_k E(x_k) P_d(|x_k - x|) dA_k. The samples x_k are a fixed
// disk pattern (a texture of offsets in mm and the area each stands for:
// uniform over the profile's reach, or placed by the profile's importance)
// laid around x in texture space at the local scale (mm per texel from the
// texel area); each sample's distance is measured between the world
// positions, its profile read from the R(r) and T(r) tables, and the two
// blended by the normals at both points (Eq. 27). For thin geometry the
// light entering the other face joins with the normal reversed, so that a
// flat slab gathers its back-lit side through T(r). Samples beyond the
// reach or off the texture-space layout carry nothing.
// A rough surface also reflects the light at its boundary: Eq. 23's
// Torrance-Sparrow lobe, under the light's pattern (surface_reflection).
// Twin: kernels/profile/profile_gather.cpp.
#include "profile_optics.glsl"
uniform sampler2D irradiance;       // texture space: rgb entering this face
uniform sampler2D irradiance_back;  // thin geometry: rgb entering the other face
uniform sampler2D position_area;    // texture space: world position, texel area
uniform sampler2D surface_normal;   // texture space: unit normal
uniform sampler2D profile_R;        // R(r) per channel at r = r_max u^2
uniform sampler2D profile_T;        // T(r), the same radii
uniform sampler2D pattern;          // one texel per sample: offset (mm), area (mm^2)
uniform int samples;
uniform float r_max;                // mm, the tables' last radius
uniform float profile_size;         // entries of each table
uniform float texel_uv;             // 1 / the texture-space targets' size
uniform int rough;                  // 1: the boundary reflects (Eq. 23)
uniform float eta;
uniform float inv_m2;               // 1 / m^2, m the RMS slope
uniform float beckmann_norm;        // 1 / (pi m^2)
uniform vec3 eye;                   // world, mm
uniform vec3 light_direction;       // unit, towards the light
uniform vec3 light_irradiance;      // on a surface facing the light, per channel
uniform vec4 spot;                  // the light's pattern, as irradiance.frag's
uniform vec4 edge;

// Eq. 27: the profile between points with normals n_s and n_l.
vec3 blended_profile(float c, vec3 R, vec3 T) {
    return 0.5 * (c + 1.0) * R + 0.5 * (1.0 - c) * T;
}

vec3 diffused_light(vec3 x, vec3 n_s, vec2 uv, bool thin) {
    float here_area = textureLod(position_area, uv, 0.0).w;
    float uv_per_mm = inversesqrt(here_area) * texel_uv;
    float table_scale = (profile_size - 1.0) / profile_size;
    float table_offset = 0.5 / profile_size;
    vec3 m = vec3(0.0);
    for (int k = 0; k < samples; ++k) {
        vec4 s = texelFetch(pattern, ivec2(k, 0), 0);
        vec2 uv_k = uv + s.xy * uv_per_mm;
        vec4 at = textureLod(position_area, uv_k, 0.0);
        vec3 n_l = textureLod(surface_normal, uv_k, 0.0).xyz;
        float r = length(at.xyz - x);
        vec2 tc = vec2(sqrt(r / r_max) * table_scale + table_offset, 0.5);
        vec3 R = textureLod(profile_R, tc, 0.0).rgb;
        vec3 T = textureLod(profile_T, tc, 0.0).rgb;
        float c = dot(n_s, n_l);
        vec3 light = textureLod(irradiance, uv_k, 0.0).rgb * blended_profile(c, R, T);
        if (thin) {
            light = light + textureLod(irradiance_back, uv_k, 0.0).rgb * blended_profile(-c, R, T);
        }
        bool on_layout = uv_k.x >= 0.0 && uv_k.x <= 1.0 && uv_k.y >= 0.0 && uv_k.y <= 1.0;
        float w = (r < r_max && on_layout) ? s.z * (at.w / here_area) : 0.0;
        m = m + light * w;
    }
    return m;
}

// The radiance the rough boundary at p reflects towards the eye: f_r of
// Eq. 23 times the irradiance there (the light's, cos theta_i, its pattern).
vec3 surface_reflection(vec3 p, vec3 n) {
    vec3 v = normalize(eye - p);
    float cos_i = max(dot(n, light_direction), 0.0);
    float f_r = torrance_sparrow(n, light_direction, v, eta, inv_m2, beckmann_norm);
    return light_irradiance * (f_r * cos_i * light_pattern(p.xy, spot, edge));
}
