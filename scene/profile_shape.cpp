// profile_shape.cpp: the shapes of profile_shape.h, their exact surfaces and
// tessellations.
#include "scene/profile_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "scene/input_error.h"
#include "scene/mesh_file.h"

namespace st {

namespace {


void push_vertex(ProfileMesh& m, const SurfacePoint& s, double u, double v) {
    m.vertices.data.push_back(glm::vec4(glm::vec3(s.position), 1.0f));
    m.vertices.data.push_back(glm::vec4(glm::vec3(s.normal), 0.0f));
    m.vertices.data.push_back(glm::vec4(float(u), float(v), 0.0f, 1.0f));
}

// The two triangles of the flat slab, as its scenes have always drawn them.
ProfileMesh slab_mesh(double size_mm) {
    ProfileMesh m;
    m.vertices.attribute_count = 3;
    const double h = 0.5 * size_mm;
    const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& k : c) {
        m.vertices.data.push_back(glm::vec4(float(k[0] * h), float(k[1] * h), 0.0f, 1.0f));
        m.vertices.data.push_back(glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
        m.vertices.data.push_back(glm::vec4(0.5f * float(k[0] + 1.0), 0.5f * float(k[1] + 1.0), 0.0f, 1.0f));
        m.bounds.push_back(glm::dvec3(k[0] * h, k[1] * h, 0.0));
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

// A grid of (nu + 1) x (nv + 1) vertices over the layout, two triangles per cell.
ProfileMesh grid_mesh(const ProfileShape& shape, int nu, int nv) {
    ProfileMesh m;
    m.vertices.attribute_count = 3;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (int j = 0; j <= nv; ++j) {
        for (int i = 0; i <= nu; ++i) {
            const double u = double(i) / nu, v = double(j) / nv;
            const SurfacePoint s = surface_point(shape, u, v);
            push_vertex(m, s, u, v);
            lo = glm::min(lo, s.position), hi = glm::max(hi, s.position);
        }
    }
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            const uint32_t a = uint32_t(j * (nu + 1) + i), b = a + 1, c = a + uint32_t(nu + 1), d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    }
    for (int k = 0; k < 8; ++k)
        m.bounds.push_back(glm::dvec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z));
    return m;
}

}  // namespace

// Every field's domain and default: scene/profile_space.cpp.
ProfileShape read_profile_shape(JsonReader& geometry) {
    ProfileShape s;
    s.kind = geometry.choice("shape");
    if (s.kind == "mesh") {
        s.mesh = std::make_shared<const ProfileMesh>(
            read_mesh_file(geometry.text("mesh_file"), geometry.field("mesh_file")));
        // The view's default distance: twice the mesh's largest extent.
        const glm::dvec3 extent = s.mesh->bounds.back() - s.mesh->bounds.front();
        s.size_mm = std::max({extent.x, extent.y, extent.z, 1e-3});
        return s;
    }
    s.size_mm = geometry.number("size_mm");
    if (s.kind == "sheet") s.bend_deg = geometry.number("bend_deg");
    if (s.kind == "ellipsoid") {
        const std::vector<double> r = geometry.numbers("radii_mm");
        s.radii = glm::dvec3(r[0], r[1], r[2]);
        s.seam_azimuth_deg = geometry.number("seam_azimuth_deg");
    }
    if (s.curved()) s.segments = geometry.integer("segments");
    return s;
}

SurfacePoint surface_point(const ProfileShape& shape, double u, double v) {
    if (shape.kind == "ellipsoid") {
        const double phi = 2.0 * std::numbers::pi * u + shape.seam_azimuth_deg * std::numbers::pi / 180.0, theta = std::numbers::pi * v;
        const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta));
        const glm::dvec3 p = shape.radii * d;
        // The gradient of |p / radii|^2, outward.
        return {p, glm::normalize(p / (shape.radii * shape.radii))};
    }
    const double h = 0.5 * shape.size_mm;
    const double x = (2.0 * u - 1.0) * h, y = (2.0 * v - 1.0) * h;
    const double bend = shape.kind == "sheet" ? shape.bend_deg * std::numbers::pi / 180.0 : 0.0;
    if (bend < 1e-9) return {glm::dvec3(x, y, 0.0), glm::dvec3(0.0, 0.0, 1.0)};
    // An arc of radius size / bend through the origin, centred on (0, 0, -radius).
    const double radius = shape.size_mm / bend, a = x / radius;
    return {glm::dvec3(radius * std::sin(a), y, radius * (std::cos(a) - 1.0)),
            glm::dvec3(std::sin(a), 0.0, std::cos(a))};
}

ProfileMesh profile_mesh(const ProfileShape& shape) {
    if (shape.kind == "mesh") return *shape.mesh;
    if (shape.kind == "slab") return slab_mesh(shape.size_mm);
    if (shape.kind == "sheet") return grid_mesh(shape, shape.segments, 2);
    return grid_mesh(shape, shape.segments, std::max(2, shape.segments / 2));
}

}  // namespace st
