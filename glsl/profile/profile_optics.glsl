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
