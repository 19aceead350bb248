// probe.h: `shadertwin probe SCENE`: where a shader and its twin first part.
// The GLSL marks values with ST_PROBE(name, value), the twin the same names
// with probe(frag, "name", value) (shading/probe.h). For each probe in the
// order the GLSL writes them, both backends render the scene with only that
// value written out, and the first probe whose bits differ is printed: its
// name, the first differing pixel, both values with their bits, and how many
// pixels differ (docs/commands.md, "probe").
#pragma once

#include <string>
#include <vector>

#include "app/commands.h"

namespace st {

// The probe names a fragment program's source marks, in the order they first
// appear (a line that #defines ST_PROBE marks nothing).
std::vector<std::string> probe_names(const std::string& source);

// The source rewritten to write only probe `name` (zero where the probe is not
// reached; the last value where it is reached more than once). Throws
// std::runtime_error when the source has no `layout(location = 0) out vec4`.
std::string probe_source(const std::string& source, const std::vector<std::string>& names, const std::string& name);

int cmd_probe(const std::string& scene, bool json, const CommonOptions& common);

}  // namespace st
