// Tests of profile_shape.h: the exact surfaces behind the tessellations.
#include "scene/profile_shape.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace st {
namespace {

TEST(ProfileShape, SheetKeepsItsSideAsArcLength) {
    ProfileShape s;
    s.kind = "sheet";
    s.size_mm = 40;
    s.bend_deg = 140;
    // Arc length along u by fine chords: the bend does not stretch the square.
    double length = 0;
    for (int k = 0; k < 4000; ++k)
        length += glm::length(surface_point(s, (k + 1) / 4000.0, 0.5).position - surface_point(s, k / 4000.0, 0.5).position);
    EXPECT_NEAR(length, 40.0, 1e-3);
    // Normals leave the surface at right angles and unit length.
    const SurfacePoint a = surface_point(s, 0.2, 0.3), b = surface_point(s, 0.2001, 0.3);
    EXPECT_NEAR(glm::length(a.normal), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(a.normal, glm::normalize(b.position - a.position)), 0.0, 1e-3);
}

TEST(ProfileShape, EllipsoidNormalsAreOutwardAndPerpendicular) {
    ProfileShape s;
    s.kind = "ellipsoid";
    s.radii = glm::dvec3(75, 90, 110);
    for (double u : {0.1, 0.4, 0.77})
        for (double v : {0.2, 0.5, 0.9}) {
            const SurfacePoint a = surface_point(s, u, v);
            const glm::dvec3 q = a.position / s.radii;
            EXPECT_NEAR(glm::dot(q, q), 1.0, 1e-12);
            EXPECT_GT(glm::dot(a.normal, a.position), 0.0);
            const glm::dvec3 tu = surface_point(s, u + 1e-6, v).position - a.position;
            const glm::dvec3 tv = surface_point(s, u, v + 1e-6).position - a.position;
            EXPECT_NEAR(glm::dot(a.normal, glm::normalize(tu)), 0.0, 1e-5);
            EXPECT_NEAR(glm::dot(a.normal, glm::normalize(tv)), 0.0, 1e-5);
        }
    // The layout's seam: u = 0 and u = 1 are the same meridian.
    EXPECT_LT(glm::length(surface_point(s, 0.0, 0.5).position - surface_point(s, 1.0, 0.5).position), 1e-9);
}

TEST(ProfileShape, MeshesCoverTheLayout) {
    ProfileShape s;
    s.kind = "ellipsoid";
    s.segments = 16;
    const ProfileMesh m = profile_mesh(s);
    EXPECT_EQ(m.vertices.vertex_count(), 17 * 9);
    EXPECT_EQ(m.indices.size(), size_t(16 * 8 * 6));
    s.kind = "slab";
    EXPECT_EQ(profile_mesh(s).indices.size(), 6u);  // the slab's two triangles, as it always was
}

}  // namespace
}  // namespace st
