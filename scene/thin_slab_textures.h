// thin_slab_textures.h: the two pictures of the thin-slab case study, made
// procedurally and deterministically (no image file ships).
#pragma once

#include "frame/frame.h"

namespace st {

// The flag of the Faroe Islands: a white field with a red Nordic cross
// fimbriated in blue, proportions 6:1:2:1:12 across and 6:1:2:1:6 up, hoist
// at u = 0. RGBA8, linear, clamp; sampler "flag".
Texture faroe_flag_texture(int width, int height);

// A watercolour-like landscape standing in for the paper's painting: sky,
// hills, sea, with soft hashed noise. RGBA8, linear, clamp; sampler "painting".
Texture painting_texture(int width, int height);

}  // namespace st
