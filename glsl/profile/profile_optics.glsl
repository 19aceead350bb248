// profile_optics.glsl: the boundary of a diffusion-profile material, shared
// by the irradiance and gather passes. Twin: kernels/profile/profile_optics.cpp.

// The unpolarised Fresnel reflectance of a smooth boundary from index 1
// into eta, cos_i and cos_t the cosines of incidence and refraction; the
// denominators are kept from 0 at grazing incidence, where it tends to 1.
float fresnel_reflectance(float eta, float cos_i, float cos_t) {
    float rs = (cos_i - eta * cos_t) / max(cos_i + eta * cos_t, 1e-6);
    float rp = (cos_t - eta * cos_i) / max(cos_t + eta * cos_i, 1e-6);
    return (rs * rs + rp * rp) * 0.5;
}

// The share of light arriving at cosine cos_i (in [0, 1]) that enters the
// material: 1 - F for a smooth boundary, the tabulated rho_dt of Eq. 26 for
// a rough one (its entries at cos = (i + 0.5) / n are the texel centres, so
// cos_i is the texture coordinate).
float transmittance_in(float cos_i, float eta, bool rough, sampler2D rho_dt) {
    float sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    float cos_t = sqrt(max(1.0 - sin2_t, 0.0));
    float smooth_t = 1.0 - fresnel_reflectance(eta, cos_i, cos_t);
    float rough_t = textureLod(rho_dt, vec2(cos_i, 0.5), 0.0).r;
    return rough ? rough_t : smooth_t;
}

// The lit share of a texel or pixel across the light pattern's boundary, s
// the signed distance from it (> 0 lit): a box filter as wide as the
// footprint across the boundary (|ds/dx| + |ds/dy| of a linear s), so that
// bilinear reads of a texture-space target put the edge where it is between
// texel centres, not at the nearest one.
float coverage(float s) {
    float w = max(fwidth(s), 1e-30);
    return min(max(s / w + 0.5, 0.0), 1.0);
}

// The ground truth's sharp-edged light on the plane of x and y
// (reference/profile_convolution.h): where a spot (xy centre, z radius;
// z <= 0: none) or an edge (lit where dot(p, edge.xy) > edge.z; w <= 0:
// none) is given, only points inside the spot or beyond the edge are lit.
float light_pattern(vec2 p, vec4 spot, vec4 edge) {
    float in_spot = spot.z > 0.0 ? coverage(spot.z - length(p - spot.xy)) : 0.0;
    // dot(p, edge.xy) - edge.z as NIR reassociates it (docs/llvmpipe/nir-algebraic.md).
    float beyond_edge = edge.w > 0.0 ? coverage(p.x * edge.x + (p.y * edge.y - edge.z)) : 0.0;
    bool patterned = spot.z > 0.0 || edge.w > 0.0;
    return patterned ? max(in_spot, beyond_edge) : 1.0;
}

// Eq. 23: the Torrance-Sparrow BRDF of the rough boundary, the one whose
// hemispherical integral is rho_dt (optics/rough_surface.h): Beckmann facets
// of RMS slope m (inv_m2 = 1 / m^2, beckmann_norm = 1 / (pi m^2)), their
// shadowing and masking, the facet's dielectric Fresnel term; l and v unit,
// towards the light and the eye.
float torrance_sparrow(vec3 n, vec3 l, vec3 v, float eta, float inv_m2, float beckmann_norm) {
    float cos_i = dot(n, l);
    float cos_o = dot(n, v);
    vec3 h = normalize(l + v);
    float nh = max(dot(n, h), 1e-6);
    float vh = max(dot(v, h), 1e-6);
    float nh2 = nh * nh;
    float tan2 = (1.0 - nh2) / nh2;
    // exp(-tan2 inv_m2) as NIR computes it: exp2 with log2(e) moved next to
    // the first factor (docs/llvmpipe/nir-algebraic.md).
    float d = exp2(-tan2 * 1.4426950408889634 * inv_m2) * beckmann_norm / (nh2 * nh2);
    float g = min(min(2.0 * nh * cos_o / vh, 2.0 * nh * cos_i / vh), 1.0);
    float sin2_t = (1.0 - vh * vh) / (eta * eta);
    float cos_t = sqrt(max(1.0 - sin2_t, 0.0));
    float f = fresnel_reflectance(eta, vh, cos_t);
    bool lit = cos_i > 0.0 && cos_o > 0.0;
    return lit ? d * g * f / max(4.0 * cos_i * cos_o, 1e-12) : 0.0;
}
