// texture_files.h: a scene's texture from image files (a user's shader
// samples the maps it was written for): one file for a 2D texture, six
// for a cube map, through OpenImageIO (PNG, EXR, HDR, JPEG, TIFF, ...).
// scene/texture_patterns.cpp reads the texture object's other fields
// (format, filters, wrap, LOD, mip chain) as for a generated pattern.
#pragma once

#include "frame/frame.h"
#include "scene/json_reader.h"
#include "scene/texture_patterns.h"

namespace st {

// Fills t's size and level 0 (every face) from `file` or `files` (paths
// already resolved against the scene's folder, scene.h), decoded per
// `colour_space` and `orientation`, in t.format. The texels are taken from
// `budget`. Errors (InputError) name the field and the file.
void read_texture_files(JsonReader& r, Texture& t, TexelBudget& budget);

}  // namespace st
