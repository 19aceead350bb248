// layer_file.h: a layer stack file for `slab --layers` and `profile
// --layers`: a JSON list, top layer first, each with sigma_a and sigma_s
// (three values, per mm), g, eta (relative to the medium above), thickness
// (mm, or "inf" for the last layer) and optional roughness (docs/optics.md).
#pragma once

#include <string>
#include <vector>

#include "optics/layered.h"

namespace st {

// Throws InputError with one line naming the file and the field.
std::vector<optics::LayerSpec> read_layer_file(const std::string& path);

}  // namespace st
