// layer_file.cpp: see layer_file.h.
#include "scene/layer_file.h"

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "scene/input_error.h"
#include "scene/json_reader.h"

namespace st {

std::vector<optics::LayerSpec> read_layer_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot read layers file " + path);
    const nlohmann::json doc = parse_json(in, path);
    if (doc.is_discarded()) throw InputError(path + ": malformed JSON");
    return parse_layers(doc, path);
}

std::vector<optics::LayerSpec> parse_layers(const nlohmann::json& doc, const std::string& path) {
    if (!doc.is_array() || doc.empty()) throw InputError(path + ": expected a non-empty JSON list of layers");
    if (doc.size() > 64) throw InputError(path + ": at most 64 layers");
    std::vector<optics::LayerSpec> layers;
    try {
        for (size_t i = 0; i < doc.size(); ++i) {
            JsonReader r(doc[i], std::to_string(i));
            optics::LayerSpec l;
            const auto a = r.numbers("sigma_a", 3, 3, 0.0, kCoefficientMax), s = r.numbers("sigma_s", 3, 3, 0.0, kCoefficientMax);
            for (int c = 0; c < 3; ++c) {
                l.sigma_a[size_t(c)] = a[size_t(c)];
                l.sigma_s[size_t(c)] = s[size_t(c)];
            }
            l.g = r.number("g", -0.999999, 0.999999);
            for (int c = 0; c < 3; ++c)
                if (!(a[size_t(c)] + s[size_t(c)] * (1.0 - l.g) >= kSigmaTReducedMin))
                    throw InputError("layer " + std::to_string(i) + ", channel " + std::to_string(c) +
                                     ": sigma_a + sigma_s (1 - g) must be at least 1e-6 per mm");
            l.eta = r.number("eta", kEtaMin, kEtaMax);
            const bool last = i + 1 == doc.size();
            if (doc[i].contains("thickness") && doc[i]["thickness"] == "inf") {
                if (!last) throw InputError("layer " + std::to_string(i) + ": only the last layer may be infinite");
                r.string("thickness");
                l.thickness = INFINITY;
            } else {
                l.thickness = r.number("thickness", kThicknessMin, kThicknessMax);
            }
            l.roughness = r.number_or("roughness", 0.0, 0.0, 10.0);
            r.finish();
            layers.push_back(l);
        }
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    // The last layer's index against the air below is the product of the
    // relative ones; it must stay in range as each given one does.
    double index = 1.0;
    for (const optics::LayerSpec& l : layers) index *= l.eta;
    if (!(index >= kEtaMin && index <= kEtaMax))
        throw InputError(path + ": the last layer's index relative to the air below, " + std::to_string(index) +
                         ", lies outside [" + std::to_string(kEtaMin) + ", " + std::to_string(kEtaMax) + "]");
    return layers;
}

}  // namespace st
