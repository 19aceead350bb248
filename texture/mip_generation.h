// mip_generation.h: mip levels made on the host, in double precision, and
// handed to both backends level by level (so neither depends on
// glGenerateMipmap and its unspecified filter).
#pragma once

#include "frame/frame.h"

namespace st {

// Level L is max(1, width >> L) x max(1, height >> L), down to 1x1.
int full_chain_levels(int width, int height);

// Fills texture.mips with levels 1..levels-1, each a box filter of level 0
// over the footprint of the destination texel (area-weighted where a size
// is odd), computed in double and stored in the texture's format (RGBA8
// rounded to nearest).
void generate_box_mips(Texture& texture, int levels);

// True when texture.mips has exactly the sizes a chain needs; else names
// the first wrong level in `why`.
bool mip_sizes_valid(const Texture& texture, std::string& why);

}  // namespace st
