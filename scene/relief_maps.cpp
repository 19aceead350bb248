// relief_maps.cpp: see relief_maps.h.
#include "scene/relief_maps.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "scene/texture_patterns.h"
#include "texture/mip_generation.h"

namespace st {

namespace {

// A uniform number in [0, 1) from a seed and up to three integers.
double random01(uint32_t seed, int a, int b = 0, int c = 0) {
    uint32_t h = hash32(seed * 0x9e3779b9u ^ hash32(uint32_t(a) * 0x85ebca6bu ^ hash32(uint32_t(b) * 0xc2b2ae35u ^
                                                                                       hash32(uint32_t(c)))));
    return double(h >> 8) / double(1u << 24);
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

double smoothstep01(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Value noise on a lattice of `period` cells per side, tileable. The
// lattice's values are drawn once per map (a texel reads four; drawing
// them per read spent most of a scene's load hashing).
struct NoiseLattice {
    NoiseLattice(uint32_t seed, int period) : period(period), value(size_t(period) * size_t(period)) {
        for (int j = 0; j < period; ++j)
            for (int i = 0; i < period; ++i) value[size_t(j) * size_t(period) + size_t(i)] = random01(seed, i, j, 7);
    }
    int period;
    std::vector<double> value;
};

double tiled_noise(const NoiseLattice& lattice, double x, double y) {
    const int period = lattice.period;
    const double fx0 = std::floor(x), fy0 = std::floor(y);
    const int ix = int(fx0), iy = int(fy0);
    const double sx = smoothstep01(x - fx0), sy = smoothstep01(y - fy0);
    auto at = [&](int i, int j) { return lattice.value[size_t(wrap(j, period)) * size_t(period) + size_t(wrap(i, period))]; };
    const double a = at(ix, iy), b = at(ix + 1, iy), c = at(ix, iy + 1), d = at(ix + 1, iy + 1);
    return (a + (b - a) * sx) * (1.0 - sy) + (c + (d - c) * sx) * sy;
}

// The stone (Voronoi cell of a jittered grid, `cells` per side, on the
// torus) nearest to a point given in cell units, and the point's distance
// to that stone's border (the nearest bisector with a neighbour).
struct StoneHit {
    int cx = 0, cy = 0;         // the stone's cell, wrapped
    double border = 0.0;        // in cell units, >= 0
    double centre = 0.0;        // distance to the stone's feature point
};

// Each cell's jitter, drawn once per map (a texel looks at 25 cells).
struct StoneLattice {
    explicit StoneLattice(const StoneParams& p) : cells(p.cells), jitter(size_t(p.cells) * size_t(p.cells) * 2) {
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i) {
                jitter[2 * (size_t(j) * size_t(cells) + size_t(i))] = random01(p.seed, i, j, 0);
                jitter[2 * (size_t(j) * size_t(cells) + size_t(i)) + 1] = random01(p.seed, i, j, 1);
            }
    }
    double at(int i, int j, int axis) const { return jitter[2 * (size_t(j) * size_t(cells) + size_t(i)) + size_t(axis)]; }
    int cells;
    std::vector<double> jitter;
};

StoneHit nearest_stone(const StoneParams& p, const StoneLattice& lattice, double qx, double qy) {
    const int bx = int(std::floor(qx)), by = int(std::floor(qy));
    double fx[25], fy[25];
    int ci[25], cj[25];
    int n = 0, best = 0;
    double best_d2 = 1e30;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx, ++n) {
            const int i = bx + dx, j = by + dy;
            ci[n] = wrap(i, p.cells);
            cj[n] = wrap(j, p.cells);
            // Jitter kept away from the cell's edges so that no stone is a sliver.
            fx[n] = i + 0.2 + 0.6 * lattice.at(ci[n], cj[n], 0);
            fy[n] = j + 0.2 + 0.6 * lattice.at(ci[n], cj[n], 1);
            const double d2 = (fx[n] - qx) * (fx[n] - qx) + (fy[n] - qy) * (fy[n] - qy);
            if (d2 < best_d2) best_d2 = d2, best = n;
        }
    StoneHit hit{ci[best], cj[best], 1e30, std::sqrt(best_d2)};
    for (int k = 0; k < n; ++k) {
        if (k == best) continue;
        const double ex = fx[k] - fx[best], ey = fy[k] - fy[best];
        const double len = std::sqrt(ex * ex + ey * ey);
        const double mx = 0.5 * (fx[k] + fx[best]), my = 0.5 * (fy[k] + fy[best]);
        hit.border = std::min(hit.border, ((mx - qx) * ex + (my - qy) * ey) / len);
    }
    hit.border = std::max(hit.border, 0.0);
    return hit;
}


Texture rgba8_trilinear(const std::string& sampler, int size) {
    Texture t;
    t.sampler = sampler;
    t.format = TextureFormat::RGBA8;
    t.mag_filter = TextureFilter::Linear;
    t.min_filter = TextureFilter::Linear;
    t.mip_filter = MipFilter::Linear;
    t.set_wrap(TextureWrap::Repeat);
    t.width = t.height = size;
    t.texels8.assign(size_t(size) * size_t(size) * 4, 0);
    return t;
}

constexpr double kJointHeight = 0.06;

}  // namespace

double HeightField::at(int x, int y) const { return h[size_t(wrap(y, size)) * size_t(size) + size_t(wrap(x, size))]; }

HeightField stone_heights(const StoneParams& p) {
    HeightField f;
    f.size = p.size;
    f.h.resize(size_t(p.size) * size_t(p.size));
    const StoneLattice stones(p);
    const NoiseLattice noise(p.seed, p.cells * 6);
    for (int y = 0; y < p.size; ++y)
        for (int x = 0; x < p.size; ++x) {
            const double qx = (x + 0.5) * p.cells / p.size, qy = (y + 0.5) * p.cells / p.size;
            const StoneHit s = nearest_stone(p, stones, qx, qy);
            // A stone: a flattish top at its own height, domed a little,
            // rounded over `bevel` down to the joint.
            const double top = 0.70 + 0.25 * random01(p.seed, s.cx, s.cy, 2);
            const double dome = 0.3 * s.centre * s.centre;
            const double edge = smoothstep01((s.border - p.mortar) / p.bevel);
            const double grain = 0.03 * (tiled_noise(noise, qx * 6.0, qy * 6.0) - 0.5);
            f.h[size_t(y) * size_t(p.size) + size_t(x)] =
                std::clamp(kJointHeight + (top - dome - kJointHeight) * edge + grain, 0.0, 1.0);
        }
    return f;
}

HeightField drop_heights(const DropParams& p) {
    HeightField f;
    f.size = p.size;
    f.h.assign(size_t(p.size) * size_t(p.size), p.level);
    for (int k = 0; k < p.drops; ++k) {
        const double cx = random01(p.seed, k, 0), cy = random01(p.seed, k, 1);
        const double r = p.min_radius + (p.max_radius - p.min_radius) * random01(p.seed, k, 2);
        const double peak = p.min_peak + (p.max_peak - p.min_peak) * random01(p.seed, k, 3);
        for (int y = 0; y < p.size; ++y)
            for (int x = 0; x < p.size; ++x) {
                // Distance on the torus, in texture coordinates.
                double dx = std::abs((x + 0.5) / p.size - cx), dy = std::abs((y + 0.5) / p.size - cy);
                dx = std::min(dx, 1.0 - dx);
                dy = std::min(dy, 1.0 - dy);
                const double q = 1.0 - (dx * dx + dy * dy) / (r * r);
                if (q <= 0.0) continue;
                // A spherical cap's profile, from the film up to the apex.
                double& h = f.h[size_t(y) * size_t(p.size) + size_t(x)];
                h = std::max(h, p.level + (peak - p.level) * std::sqrt(q));
            }
    }
    return f;
}

Texture relief_texture(const HeightField& field, double depth, const std::string& sampler) {
    Texture t = rgba8_trilinear(sampler, field.size);
    const double texel = 1.0 / field.size;
    for (int y = 0; y < field.size; ++y)
        for (int x = 0; x < field.size; ++x) {
            const double dhdu = (field.at(x + 1, y) - field.at(x - 1, y)) / (2.0 * texel);
            const double dhdv = (field.at(x, y + 1) - field.at(x, y - 1)) / (2.0 * texel);
            const double nx = -depth * dhdu, ny = -depth * dhdv, nz = 1.0;
            const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
            uint8_t* o = &t.texels8[(size_t(y) * size_t(field.size) + size_t(x)) * 4];
            o[0] = unit_to_byte(nx / len * 0.5 + 0.5);
            o[1] = unit_to_byte(ny / len * 0.5 + 0.5);
            o[2] = unit_to_byte(nz / len * 0.5 + 0.5);
            o[3] = unit_to_byte(field.at(x, y));
        }
    generate_box_mips(t, full_chain_levels(t.width, t.height));
    return t;
}

Texture stone_colour_texture(const StoneParams& p, const std::string& sampler) {
    Texture t = rgba8_trilinear(sampler, p.size);
    const StoneLattice stones(p);
    const NoiseLattice noise(p.seed + 1, p.cells * 12);
    for (int y = 0; y < p.size; ++y)
        for (int x = 0; x < p.size; ++x) {
            const double qx = (x + 0.5) * p.cells / p.size, qy = (y + 0.5) * p.cells / p.size;
            const StoneHit s = nearest_stone(p, stones, qx, qy);
            const double tone = random01(p.seed, s.cx, s.cy, 3), bright = 0.8 + 0.3 * random01(p.seed, s.cx, s.cy, 4);
            const double grain = 0.88 + 0.24 * tiled_noise(noise, qx * 12.0, qy * 12.0);
            // Stones between a warm grey-brown and a cool grey; joints a pale mortar.
            double rgb[3] = {(0.47 + 0.15 * tone) * bright, (0.42 + 0.18 * tone) * bright,
                             (0.36 + 0.20 * tone) * bright};
            const double joint = 1.0 - smoothstep01((s.border - p.mortar) / (0.25 * p.bevel));
            const double mortar[3] = {0.70, 0.68, 0.63};
            uint8_t* o = &t.texels8[(size_t(y) * size_t(p.size) + size_t(x)) * 4];
            for (int c = 0; c < 3; ++c) o[c] = unit_to_byte((rgb[c] + (mortar[c] - rgb[c]) * joint) * grain);
            o[3] = 255;
        }
    generate_box_mips(t, full_chain_levels(t.width, t.height));
    return t;
}

glm::dvec3 cube_texel_direction(int face, double sc, double tc) {
    // GL's face selection (OpenGL 4.5, Table 8.19) inverted: sc, tc in [-1, 1].
    switch (face) {
    case 0: return {1.0, -tc, -sc};   // +X
    case 1: return {-1.0, -tc, sc};   // -X
    case 2: return {sc, 1.0, tc};     // +Y
    case 3: return {sc, -1.0, -tc};   // -Y
    case 4: return {sc, -tc, 1.0};    // +Z
    default: return {-sc, -tc, -1.0}; // -Z
    }
}

Texture sky_cube_texture(int size, glm::dvec3 sun_direction, double sun_radiance, double sun_radius_deg,
                         const std::string& sampler) {
    Texture t;
    t.sampler = sampler;
    t.format = TextureFormat::RGBA32F;
    t.set_filter(TextureFilter::Linear);
    t.set_wrap(TextureWrap::ClampToEdge);
    t.cube = true;
    t.width = t.height = size;
    t.texels32.reserve(size_t(6) * size_t(size) * size_t(size) * 4);
    const glm::dvec3 sun = glm::normalize(sun_direction);
    const double cos_disc = std::cos(sun_radius_deg * 3.14159265358979323846 / 180.0);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::dvec3 d =
                    glm::normalize(cube_texel_direction(face, 2.0 * (x + 0.5) / size - 1.0, 2.0 * (y + 0.5) / size - 1.0));
                double rgb[3];
                if (d.z >= 0.0) {
                    // Paler towards the horizon.
                    const double k = std::pow(1.0 - d.z, 3.0);
                    const double zenith[3] = {0.25, 0.45, 0.95}, horizon[3] = {0.85, 0.88, 0.95};
                    for (int c = 0; c < 3; ++c) rgb[c] = 1.5 * (zenith[c] + (horizon[c] - zenith[c]) * k);
                } else {
                    const double ground[3] = {0.22, 0.2, 0.17};
                    for (int c = 0; c < 3; ++c) rgb[c] = ground[c];
                }
                const double cos_sun = glm::dot(d, sun);
                const double glow = std::pow(std::max(cos_sun, 0.0), 64.0) * 4.0;
                const double disc = cos_sun >= cos_disc ? sun_radiance : 0.0;
                const double warm[3] = {1.0, 0.9, 0.75};
                for (int c = 0; c < 3; ++c) t.texels32.push_back(float(rgb[c] + (glow + disc) * warm[c]));
                t.texels32.push_back(1.0f);
            }
    return t;
}

}  // namespace st
