// pass_times.h: each pass's cost on both backends, for the per-pass fps
// tables (`bench --passes`). Neither backend times its passes apart, so the
// frame is run cut after each pass (the earlier passes only, then an empty
// frame pass, which both backends clear) and a pass costs the difference of
// the medians of the cut before and after it, the cuts and backends
// interleaved round by round. Differences of medians: noisy for a pass far
// cheaper than the rest; quote it with the whole frame's numbers.
#pragma once

#include <string>
#include <vector>

#include "app/backends.h"
#include "frame/frame.h"

namespace st {

struct PassTime {
    std::string name;  // the target drawn, or "frame"
    double cpu_ms = 0, gl_ms = 0;
};

std::vector<PassTime> measure_pass_times(Backends& backends, const Frame& frame, int rounds);

}  // namespace st
