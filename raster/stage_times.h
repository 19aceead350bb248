// stage_times.h: where a CPU frame's time goes, per pipeline stage.
//
// Vertex and setup/binning run before the tile phase and are wall-clock
// times. Rasterization, fragment shading and blending/output interleave per
// tile on every worker, so they are summed over workers (CPU time) and then
// scaled to share the tile phase's wall-clock time in proportion; the five
// stages therefore add up to the frame's wall-clock time.
#pragma once

#include <chrono>

namespace st {

struct StageTimes {
    double vertex_ms = 0, setup_ms = 0, raster_ms = 0, fragment_ms = 0, output_ms = 0;
    double total_ms() const { return vertex_ms + setup_ms + raster_ms + fragment_ms + output_ms; }
    StageTimes& operator+=(const StageTimes& o) {
        vertex_ms += o.vertex_ms; setup_ms += o.setup_ms; raster_ms += o.raster_ms;
        fragment_ms += o.fragment_ms; output_ms += o.output_ms;
        return *this;
    }
};

using Clock = std::chrono::steady_clock;

inline double ms_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace st
