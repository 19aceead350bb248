// mesh_file.h: a diffusion-profile scene's own mesh, from a Wavefront OBJ
// file (geometry.shape "mesh", geometry.mesh_file). The irradiance and
// surface passes draw the mesh at its texture coordinates (Donner and
// Jensen Sec. 3), so every face corner needs one (v/vt or v/vt/vn), each in
// [0, 1]; the layout should cover each surface point once (not checked:
// overlapping charts sum their light). Normals come from vn, else from each
// face's plane. Polygons are split into fans of triangles. Anything else
// (groups, materials, lines) is skipped. A bad file is refused with one line
// naming the field, the file and the line.
#pragma once

#include <string>

#include "scene/profile_shape.h"

namespace st {

ProfileMesh read_mesh_file(const std::string& path, const std::string& field);

}  // namespace st
