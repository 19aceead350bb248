// fields.cpp: `shadertwin fields` (see fields.h). Each kind's table sits in
// docs/scenes.md between "<!-- fields KIND -->" and "<!-- end fields -->";
// scripts/update-scene-docs.sh rewrites them from this output, and
// cli.scene_docs fails when they differ.
#include "app/commands/fields.h"

#include <iostream>

#include "scene/input_error.h"
#include "scene/param_space.h"

namespace st {

int cmd_fields(const std::vector<std::string>& kinds) {
    const std::vector<std::string> wanted = kinds.empty() ? spaced_kinds() : kinds;
    for (const std::string& k : wanted)
        if (!kind_space(k)) throw InputError("scene kind '" + k + "' declares no parameter space");
    for (const std::string& k : wanted) {
        std::cout << "<!-- fields " << k << " -->\n" << kind_space(k)->markdown() << "<!-- end fields -->\n";
    }
    return 0;
}

}  // namespace st
