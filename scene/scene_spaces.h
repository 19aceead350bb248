// scene_spaces.h: the declared parameter space of each built-in scene kind
// (scene/param_space.h), one file per kind: scene/<kind>_space.cpp.
#pragma once

#include "scene/param_space.h"

namespace st {

const ParamSpace& triangles_space();
const ParamSpace& conformance_space();
const ParamSpace& thin_slab_space();
const ParamSpace& relief_space();
const ParamSpace& profile_space();

}  // namespace st
