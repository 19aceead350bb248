// thin_slab_speed.h: the thin slab's speed against its accuracy (issue 28),
// part of `sweep thin-slab`: the four variants (baseline, vertex, host,
// fragment) at six flag mesh resolutions on three light paths (backlit,
// frontlit, a light near the flag's plane), each CPU frame timed (median
// of interleaved rounds) and its image compared with the fragment variant
// in exact arithmetic (thin_slab_exact.h): RMS over the flag's pixels in
// 8-bit steps, and the share more than a step off. Per light path a chart
// of error against time, the undominated settings joined and the variant
// `quality: auto` takes at each mesh (thin_slab_quality.h) marked.
#pragma once

#include <string>

namespace st {

struct CommonOptions;

// Writes thin-slab-speed.csv and thin-slab-speed-<path>.svg into out_dir;
// returns the Markdown section.
std::string thin_slab_speed_accuracy(const std::string& out_dir, int frames, const CommonOptions& common);

}  // namespace st
