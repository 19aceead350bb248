// fields.h: `shadertwin fields`, the declared parameter space of each scene
// kind (scene/param_space.h) as the Markdown tables docs/scenes.md holds.
#pragma once

#include <string>
#include <vector>

namespace st {

// `kinds` empty: every kind with a declared space.
int cmd_fields(const std::vector<std::string>& kinds);

}  // namespace st
