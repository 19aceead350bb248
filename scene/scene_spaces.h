// scene_spaces.h: the declared parameter space of each built-in scene kind
// (scene/param_space.h), one file per kind: scene/<kind>_space.cpp.
#pragma once

#include "scene/param_space.h"

namespace st {

// The largest colour (clear colours included) a triangle list takes, and a
// conformance scene's texture coordinate: scene/shared_spaces.cpp says why.
inline constexpr double kMaxAttribute = 1e6;

const ParamSpace& triangles_space();
const ParamSpace& conformance_space();
const ParamSpace& thin_slab_space();
const ParamSpace& relief_space();
const ParamSpace& profile_space();

// Blocks of fields more than one kind declares (scene/shared_spaces.cpp), to
// include under a prefix. A procedural texture (scene/texture_patterns.h),
// without its `sampler`; `render_targets`: it may name one instead.
ParamSpace pattern_texture_fields(bool render_targets);
// The list of triangles (scene/triangle_list.h), under "triangles": positions
// in pixels only (else clip space too), white when no colour is given, uvs
// always (else only with a texture), uvs within +-max_uv.
ParamSpace triangle_list_fields(bool pixels_only, bool colour_optional, bool uvs_always, double max_uv,
                                bool required = true);

}  // namespace st
