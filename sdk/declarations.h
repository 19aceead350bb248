// declarations.h: the techniques a tool's source files declared (each
// TechniqueDeclaration adds itself while the program starts), for
// run_tool to take in.
#pragma once

#include <vector>

#include "sdk/technique.h"

namespace st {

std::vector<const TechniqueDeclaration*>& declared_techniques();

}  // namespace st
