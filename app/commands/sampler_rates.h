// sampler_rates.h: `shadertwin bench --samplers`: samples per second of each
// sampler entry point (texture() with the quad's implicit LOD, textureLod,
// textureGrad, and the three on a cube map) for each format and filter, on
// both backends (issue 30). Each case is a conformance scene made here: the
// entry point's conformance program (glsl/conformance/sample_*.frag) on a
// 512x512 quad, one read a pixel, so a rate is pixels a second of that
// program (interpolation and output included, the same on both sides), and
// the ratio says where the general sampler path stands against llvmpipe's.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.h"

namespace st {

struct SamplerCase {
    std::string entry;   // "texture", "textureLod", "textureGrad", "cube texture", ...
    std::string format;  // a texture format as scenes spell it: "rgba8", "r32f", ...
    std::string filter;  // the min filter: "nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_linear"
    std::string name() const;  // "sampler-rate-texture-rgba8-linear_mipmap_linear"
};

// Every case, entry point by entry point.
std::vector<SamplerCase> sampler_cases();

// The conformance scene document of one case.
nlohmann::json sampler_case_document(const SamplerCase& c);

int cmd_bench_samplers(int frames, bool json, const CommonOptions& common);

}  // namespace st
