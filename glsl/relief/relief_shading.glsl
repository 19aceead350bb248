// relief_shading.glsl: the lighting every relief row shares: Blinn-Phong
// with an ambient term and a white highlight of exponent 32 (five
// squarings, so that no pow() and its log2/exp2 approximations enter).
// Twin: kernels/relief/relief_shading.cpp.

// `light` is the light that reaches the point (Algorithm 2's coefficient,
// per channel); blinn_phong() is the fully lit case (multiplying by 1
// changes no bit).
// The highlight's shape: max(dot(n, h), 0)^32, h halfway between l and v.
float highlight32(vec3 n, vec3 l, vec3 v) {
    vec3 h = normalize(l + v);
    float s = max(dot(n, h), 0.0);
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    return s;
}

vec3 lit_blinn_phong(vec3 albedo, vec3 n, vec3 l, vec3 v, float ambient, float specular, vec3 light) {
    float diffuse = max(dot(n, l), 0.0);
    float s = highlight32(n, l, v);
    return albedo * (ambient + diffuse * light) + vec3(specular * s) * light;
}

vec3 blinn_phong(vec3 albedo, vec3 n, vec3 l, vec3 v, float ambient, float specular) {
    return lit_blinn_phong(albedo, n, l, v, ambient, specular, vec3(1.0));
}

// A relief map texel's normal: stored n * 0.5 + 0.5 in RGB.
vec3 decode_normal(vec4 texel) {
    return normalize(texel.rgb * 2.0 - 1.0);
}

// Timonen Sec. 2 (after Blinn): the unpolarised Fresnel reflectance at a
// boundary from index n1 into n2, cos_i the cosine of the angle of
// incidence (a1), cos_t that of refraction (a3); I_refr = 1 - I_refl. The
// denominators are kept from 0 (grazing on both sides), where the terms
// tend to 1.
float fresnel_reflectance(float n1, float n2, float cos_i, float cos_t) {
    float rs = (n1 * cos_i - n2 * cos_t) / max(n1 * cos_i + n2 * cos_t, 1e-6);
    float rp = (n1 * cos_t - n2 * cos_i) / max(n1 * cos_t + n2 * cos_i, 1e-6);
    return (rs * rs + rp * rp) * 0.5;
}
