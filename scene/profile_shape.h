// profile_shape.h: the geometry of a diffusion-profile scene, no richer
// than its material needs, each shape with a texture layout that covers the
// texture-space targets once (Donner and Jensen Sec. 3 render irradiance
// and positions in texture space):
//   slab       a square of side size_mm in z = 0 facing +z, uv spanning it
//              (the ground truth's flat slab: reference/profile_convolution.h);
//   sheet      the same square bent about the y axis through bend_deg of arc,
//              bulging towards +z (an ear, a leaf, a thin jade panel); past
//              180 degrees its arms face each other (Eq. 27's failure);
//   ellipsoid  semi-axes radii, u the azimuth about z (the seam where the
//              layout's u wraps, at seam_azimuth_deg), v from the -z pole to
//              the +z pole (a head, a marble block).
//   mesh       the user's own, from an OBJ file with its layout
//              (scene/mesh_file.h); it has no exact surface here, so
//              texturing, thickness maps and exact images refuse it.
// point() is the exact surface that mesh() tessellates, for the host's own
// convolutions (Sec. 3.1 texturing) and the exact images.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "frame/frame.h"
#include "scene/json_reader.h"

namespace st {

// Vertex attributes of every profile program: position, normal, uv.
struct ProfileMesh {
    VertexArray vertices;
    std::vector<uint32_t> indices;
    std::vector<glm::dvec3> bounds;  // points whose hull holds it, for the camera's near and far
};

// (A field added here that surface_point() reads joins the key of
// scene_albedo_texture(), profile_albedo.cpp.)
struct ProfileShape {
    std::string kind = "slab";  // "slab", "sheet", "ellipsoid"
    double size_mm = 40;        // slab, sheet: the side
    double bend_deg = 0;        // sheet: arc of the bend along x
    glm::dvec3 radii{20, 20, 20};   // ellipsoid, mm
    double seam_azimuth_deg = 90;   // ellipsoid: azimuth of u = 0 and 1 (default +y, away from the default view)
    int segments = 64;          // sheet, ellipsoid: quads around (half as many pole to pole)
    std::shared_ptr<const ProfileMesh> mesh;  // mesh: as read from geometry.mesh_file
    bool curved() const { return kind != "slab"; }
    bool exact() const { return kind != "mesh"; }  // surface_point() knows it
};

// Reads the geometry object's shape fields (the caller finishes it).
ProfileShape read_profile_shape(JsonReader& geometry);

struct SurfacePoint {
    glm::dvec3 position;  // mm
    glm::dvec3 normal;    // unit, outward
};
SurfacePoint surface_point(const ProfileShape& shape, double u, double v);

ProfileMesh profile_mesh(const ProfileShape& shape);

}  // namespace st
