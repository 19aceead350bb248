// triangle_list.h: the "triangles" array shared by the triangles and
// conformance kinds: positions in clip space or pixels, per-vertex colours
// and, for textured programs, uvs. Appends to a draw whose vertex program
// takes position, colour[, uv] (glsl/triangles/interp.vert, textured.vert).
#pragma once

#include "frame/frame.h"
#include "raster/viewport.h"
#include "scene/json_reader.h"
#include "scene/scene_kinds.h"

namespace st {

struct TriangleListFormat {
    bool pixels = false;      // positions in window pixels, else clip space
    bool uvs = false;         // each triangle has "uvs"
    bool colour_optional = false;  // no colour means white
};

// An RGB or RGBA colour as a scene file gives it (alpha 1 when absent).
glm::vec4 rgba(const std::vector<double>& v);

// Positions pass the vertex program unchanged, so each triangle is checked
// here, clipped to `viewport` as the pipeline clips it: one whose window
// positions cannot be snapped is refused (raster/setup_reach.h).
void read_triangle_list(JsonReader& scene, SceneSize size, const Viewport& viewport, TriangleListFormat format,
                        DrawCall& draw);

}  // namespace st
