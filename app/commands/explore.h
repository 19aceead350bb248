// explore.h: `shadertwin explore`, settings nobody chose, drawn from each
// scene kind's declared space (scene/param_space.h) and compared on both
// backends; every failure shrunk to the fewest changed fields and written
// as a standalone scene file (docs/commands.md, "explore").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/commands.h"

namespace st {

struct ExploreOptions {
    std::vector<std::string> targets;  // kinds, scene names or paths; empty: every kind with a space
    uint64_t seed = 1;
    long cases = 100;       // at most this many cases
    double seconds = 0;     // and no new case after this long; 0: no limit
    int max_fields = 3;     // fields changed per case: 1 to this
    std::string out_dir = "explore";
    bool json = false;      // the summary on stdout as JSON
};

int cmd_explore(const ExploreOptions& options, const CommonOptions& common);

}  // namespace st
