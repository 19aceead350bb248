// tool_data.h: where the tool reads its shaders and data. A build tree's
// tool reads the source tree (glsl/, scenes/, tests/golden/, materials/);
// an installed one reads <prefix>/share/shadertwin/, laid out alike (glsl/,
// scenes/, golden/hashes.json, materials/); a user's tool adds its own
// techniques' GLSL files (sdk/technique.h).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace st {

// Reads the built-in shaders, scenes, goldens and materials from an
// installed share/shadertwin folder. Throws std::runtime_error when the
// folder does not hold them.
void set_builtin_data_dir(const std::string& share_dir);
// The share/shadertwin folder beside an installed executable
// (<prefix>/bin/x -> <prefix>/share/shadertwin), or "" when there is none.
std::string installed_data_dir_beside(const std::string& executable);

void add_glsl_roots(const std::vector<std::string>& roots);
// The built-in glsl/ folder first, then every user technique's files.
std::vector<std::string> glsl_roots();
std::string materials_dir();
// Per technique (scene kind), the folder holding its sweep's last kept run
// (`sweep relief --out DIR`: SVG charts, CSV, Markdown), which `report`
// shows: relief and profile.
std::map<std::string, std::string> sweep_chart_dirs();

// The tool's name as its users call it (`shadertwin`, or a user tool's), for
// the commands that reports and JUnit files quote.
void set_tool_name(const std::string& name);
const std::string& tool_name();

}  // namespace st
