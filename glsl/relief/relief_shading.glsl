// relief_shading.glsl: the lighting every relief row shares: Blinn-Phong
// with an ambient term and a white highlight of exponent 32 (five
// squarings, so that no pow() and its log2/exp2 approximations enter).
// Twin: kernels/relief/relief_shading.cpp.

vec3 blinn_phong(vec3 albedo, vec3 n, vec3 l, vec3 v, float ambient, float specular) {
    float diffuse = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float s = max(dot(n, h), 0.0);
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    return albedo * (ambient + diffuse) + vec3(specular * s);
}

// A relief map texel's normal: stored n * 0.5 + 0.5 in RGB.
vec3 decode_normal(vec4 texel) {
    return normalize(texel.rgb * 2.0 - 1.0);
}
