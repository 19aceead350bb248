// layer_file.h: a layer stack file for `slab --layers`, `profile --layers`
// and a profile scene's material: a JSON list, top layer first, each with sigma_a and sigma_s
// (three values, per mm), g, eta (relative to the medium above), thickness
// (mm, or "inf" for the last layer) and optional roughness (docs/optics.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "optics/layered.h"

namespace st {

// What a slab may be, on the command line and in a file: beyond these the
// arithmetic overflows (sigma_tr^2) or the boundary becomes a mirror.
constexpr double kCoefficientMax = 1e9;          // sigma_a, sigma_s, per mm
constexpr double kSigmaTReducedMin = 1e-6;       // per mm: a mean free path of at most a kilometre
constexpr double kEtaMin = 0.01, kEtaMax = 100;  // every relative index, inner interfaces included
constexpr double kThicknessMin = 1e-12, kThicknessMax = 1e9;  // mm

// Throws InputError with one line naming the file and the field.
std::vector<optics::LayerSpec> read_layer_file(const std::string& path);
// The same for a list already parsed (a scene's inline layers); `where`
// opens each message.
std::vector<optics::LayerSpec> parse_layers(const nlohmann::json& list, const std::string& where);

}  // namespace st
