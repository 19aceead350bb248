// cli.h: the `shadertwin` command line, shared by the built-in tool and a
// user's (sdk/tool.h).
#pragma once

#include <functional>

namespace st {

// Parses the command line and runs its command. `setup` runs after the
// command line parsed and before the command, inside the error handling:
// what it throws ends the tool with one line on stderr and exit code 2.
int run_cli(int argc, char** argv, const std::function<void()>& setup);

}  // namespace st
