// image_budget.cpp: see image_budget.h.
#include "app/quality/image_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "app/median.h"
#include "image/unorm8.h"
#include "raster/cpu_renderer.h"
#include "raster/stage_times.h"
#include "scene/input_error.h"

namespace st {

ObjectError object_error(const Image& candidate, const Image& reference, double budget) {
    std::vector<double> d;
    for (size_t p = 0; p + 3 < reference.rgba.size(); p += 4) {
        bool object = false;
        double worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const uint8_t x = to_unorm8(candidate.rgba[p + c]), r = to_unorm8(reference.rgba[p + c]);
            object |= x != 0 || r != 0;
            worst = std::max(worst, std::abs(double(x) - double(r)));
        }
        if (object) d.push_back(worst);
    }
    ObjectError e;
    if (d.empty()) return e;
    e.over_budget = double(std::count_if(d.begin(), d.end(), [&](double x) { return x > budget; })) / double(d.size());
    std::sort(d.begin(), d.end());
    e.p99 = d[std::min(d.size() - 1, size_t(0.99 * double(d.size())))];
    e.max = d.back();
    return e;
}

double read_quality_budget(const nlohmann::json& document, const std::string& what) {
    const nlohmann::json& q = document.at("quality");
    if (!q.is_string() || q.get<std::string>() != "auto")
        throw InputError("field 'quality' must be \"auto\" (" + what + " within the budget)");
    if (!document.contains("quality_budget")) return kDefaultQualityBudget;
    const nlohmann::json& b = document.at("quality_budget");
    if (!b.is_number() || !(b.get<double>() >= 0.5 && b.get<double>() <= 64.0))
        throw InputError("field 'quality_budget' must be a number of 8-bit steps in [0.5, 64]");
    return b.get<double>();
}

double median_frame_ms(CpuRenderer& renderer, const Frame& frame, int frames) {
    renderer.prepare(frame);
    std::vector<double> ms;
    for (int f = 0; f < std::max(1, frames); ++f) {
        const auto t0 = Clock::now();
        renderer.execute();
        ms.push_back(ms_between(t0, Clock::now()));
    }
    return median(ms);
}

nlohmann::json without_quality_fields(const nlohmann::json& document) {
    nlohmann::json d = document;
    d.erase("quality");
    d.erase("quality_budget");
    return d;
}

std::string quality_choice_key(const std::string& rule, const nlohmann::json& document, double budget) {
    const nlohmann::json base = without_quality_fields(document);
    std::ostringstream key;
    key.precision(17);
    key << rule << " budget " << budget << ' ' << base.dump();
    return key.str();
}

}  // namespace st
