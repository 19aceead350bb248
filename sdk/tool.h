// tool.h: a shadertwin tool's entry point, the built-in `shadertwin` and a
// user's (shadertwin_add_technique builds one with sdk/tool_main.cpp).
#pragma once

namespace st {

// Finds the tool's data (an installed tool's share/shadertwin, else the
// source tree it was built from), takes in every declared technique
// (sdk/technique.h) and runs the command line. A technique that cannot be
// taken in (a missing GLSL file, a twin or scene kind registered twice, a
// scene name that is taken) ends the tool with one line and exit code 2.
int run_tool(int argc, char** argv);

}  // namespace st
