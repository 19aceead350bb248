// relief_quality.cpp: `quality: auto` for relief scenes (relief_quality.h).
#include "app/quality/relief_quality.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "app/quality/measured_costs.h"
#include "app/quality/relief_exact.h"
#include "raster/cpu_renderer.h"
#include "scene/input_error.h"
#include "scene/scene.h"

namespace st {

namespace {

const std::vector<std::string> kTwoLayerRows = {"two-layer", "occlusion", "absorption"};
const std::vector<std::string> kOccludingRows = {"occlusion", "absorption"};
bool is_one_of(const std::string& s, const std::vector<std::string>& set) {
    return std::find(set.begin(), set.end(), s) != set.end();
}

// The search candidates: every count of linear and binary steps (with and
// without the secant step), and for relief mapping the counts scaled by
// the view angle.
constexpr int kLinearSteps[] = {1, 2, 4, 8, 16, 32, 64, 128, 256};
constexpr int kBinarySteps[] = {0, 1, 2, 4, 6, 8, 12};
constexpr std::pair<int, int> kScaled[] = {{32, 8}, {64, 8}, {64, 16}, {128, 16}};
constexpr int kCrossings[] = {1, 2, 4, 8};  // tried fewest first; 16 is the most accurate setting's

// In the cost order: cheapest first by `cost`; at equal cost the secant
// step first (it costs nothing measurable and is more accurate), then fewer
// binary steps, then a fixed count before a scaled one: a total order, so
// the choice is one.
std::vector<ReliefCandidate> search_candidates(const std::string& technique, double angle_deg, const ReliefCost& cost) {
    std::vector<ReliefCandidate> out;
    for (const ReliefSetting& s : relief_search_settings(technique)) out.push_back(ReliefCandidate{s, cost(s, angle_deg), {}});
    std::stable_sort(out.begin(), out.end(), [](const ReliefCandidate& a, const ReliefCandidate& b) {
        const ReliefSetting &p = a.setting, &q = b.setting;
        return std::make_tuple(a.cost, !p.secant, p.binary_steps, p.min_linear_steps, p.linear_steps) <
               std::make_tuple(b.cost, !q.secant, q.binary_steps, q.min_linear_steps, q.linear_steps);
    });
    return out;
}

}  // namespace

std::vector<ReliefSetting> relief_search_settings(const std::string& technique) {
    std::vector<ReliefSetting> out;
    for (int linear : kLinearSteps)
        for (int binary : kBinarySteps)
            for (bool secant : {true, false}) {
                ReliefSetting s;
                s.linear_steps = linear, s.binary_steps = binary, s.secant = secant;
                out.push_back(s);
            }
    if (technique == "relief")
        for (auto [hi, lo] : kScaled)
            for (int binary : {4, 6}) {
                ReliefSetting s;
                s.linear_steps = hi, s.min_linear_steps = lo, s.binary_steps = binary;
                out.push_back(s);
            }
    out.push_back(ReliefSetting{});  // the most accurate
    return out;
}

std::string ReliefSetting::label() const {
    std::ostringstream s;
    if (min_linear_steps > 0) s << "mix(" << linear_steps << "," << min_linear_steps << ")";
    else s << linear_steps;
    s << " / " << binary_steps << (secant ? " / secant" : " / -");
    if (planar) s << ", planar";
    if (max_crossings != ReliefSetting{}.max_crossings) s << ", " << max_crossings << " crossings";
    return s.str();
}

double relief_quality_budget(const nlohmann::json& document) {
    return read_quality_budget(document, "the cheapest search");
}

nlohmann::json with_relief_setting(const nlohmann::json& document, const ReliefSetting& s) {
    nlohmann::json d = without_quality_fields(document);
    const std::string technique = d.value("technique", std::string("relief"));
    if (technique == "normal-mapping") return d;  // reads no search
    auto object = [&](const char* key) -> nlohmann::json& {
        if (!d.contains(key)) d[key] = nlohmann::json::object();
        if (!d[key].is_object()) throw InputError(std::string("field '") + key + "' must be an object");
        return d[key];
    };
    nlohmann::json& search = object("search");
    search["linear_steps"] = s.linear_steps;
    search["binary_steps"] = s.binary_steps;
    search["secant"] = s.secant;
    if (technique == "relief") search["min_linear_steps"] = s.min_linear_steps;
    if (is_one_of(technique, kTwoLayerRows)) object("reflections")["planar"] = s.planar;
    if (is_one_of(technique, kOccludingRows)) object("liquid")["max_crossings"] = s.max_crossings;
    return d;
}

ReliefQualityChoice measure_relief_quality(const ReliefSweepTwins& twins, int threads, const std::string& name,
                                           const nlohmann::json& document, int frames, const ReliefCost& cost) {
    ReliefQualityChoice choice;
    choice.scene = name;
    choice.budget = relief_quality_budget(document);
    choice.technique = document.value("technique", std::string("relief"));
    if (choice.technique == "normal-mapping") {
        choice.nothing_to_choose = true;
        choice.reference = "none: normal mapping has no search";
        return choice;
    }
    double angle = 45.0;
    if (document.contains("view") && document["view"].is_object() && document["view"].contains("angle_deg") &&
        document["view"]["angle_deg"].is_number())
        angle = document["view"]["angle_deg"].get<double>();

    choice.angle_deg = angle;
    CpuRenderer renderer(threads, twins);
    const Scene most_accurate = load_scene_document(name, with_relief_setting(document, ReliefSetting{}), "");
    const Image most_accurate_image = renderer.render(most_accurate.frame);
    // The reference: every search replaced by the exact crossing of the
    // height map the sampler reads (relief_exact.h), at the most accurate
    // setting's other knobs (searched reflections, 16 light crossings).
    const auto with_program = [&](const std::string& from, const char* to) {
        Frame f = most_accurate.frame;
        for (Pass& pass : f.passes)
            for (DrawCall& d : pass.draws)
                if (d.fragment == from) d.fragment = to;
        return f;
    };
    const Image reference = renderer.render(choice.technique == "relief"
                                                ? with_program("relief_mapping", ReliefSweepTwins::kSampledReliefMapping)
                                                : with_program("two_layer", ReliefSweepTwins::kSampledTwoLayer));
    if (const std::string e = twins.take_error(); !e.empty())
        throw std::runtime_error("quality auto: " + name + ": the exact image failed: " + e);
    choice.reference = "the exact crossings of the height maps as the sampler reads them";
    choice.most_accurate_error = object_error(most_accurate_image, reference, choice.budget);
    const auto try_setting = [&](ReliefCandidate c) {
        const Scene scene = load_scene_document(name, with_relief_setting(document, c.setting), "");
        c.error = object_error(renderer.render(scene.frame), reference, choice.budget);
        choice.tried.push_back(c);
        return c.error.within();
    };
    // 1. The search, the other knobs at their most accurate.
    for (const ReliefCandidate& c : search_candidates(choice.technique, angle, cost))
        if (try_setting(c)) {
            choice.chosen = int(choice.tried.size()) - 1;
            break;
        }
    if (choice.chosen >= 0) {
        // 2. Planar reflections, when the image stays within the budget.
        if (is_one_of(choice.technique, kTwoLayerRows)) {
            ReliefCandidate c = choice.tried[size_t(choice.chosen)];
            c.setting.planar = true;
            if (try_setting(c)) choice.chosen = int(choice.tried.size()) - 1;
        }
        // 3. The fewest light crossings within the budget.
        if (is_one_of(choice.technique, kOccludingRows))
            for (int crossings : kCrossings) {
                ReliefCandidate c = choice.tried[size_t(choice.chosen)];
                c.setting.max_crossings = crossings;
                if (try_setting(c)) {
                    choice.chosen = int(choice.tried.size()) - 1;
                    break;
                }
            }
    }
    const Scene chosen = load_scene_document(name, with_relief_setting(document, choice.setting()), "");
    if (choice.technique == "relief") {
        // The floor no search passes: both against the bilinear surface's
        // crossing in exact arithmetic.
        const Image bilinear = renderer.render(with_program("relief_mapping", ReliefSweepTwins::kExactReliefMapping));
        if (const std::string e = twins.take_error(); !e.empty())
            throw std::runtime_error("quality auto: " + name + ": the bilinear exact image failed: " + e);
        choice.exact_chosen = object_error(renderer.render(chosen.frame), bilinear, choice.budget);
        choice.exact_most_accurate = object_error(most_accurate_image, bilinear, choice.budget);
        choice.have_exact = true;
    }
    choice.chosen_ms = median_frame_ms(renderer, chosen.frame, frames);
    choice.most_accurate_ms = median_frame_ms(renderer, most_accurate.frame, frames);
    return choice;
}

nlohmann::json relief_choice_record(const ReliefQualityChoice& choice) {
    nlohmann::json r = {{"technique", "relief"}, {"row", choice.technique}, {"budget", choice.budget},
                        {"reference", choice.reference}};
    if (choice.nothing_to_choose) {
        r["setting"] = "nothing to choose";
        return r;
    }
    const ReliefSetting s = choice.setting();
    r["setting"] = s.label();
    r["fields"] = {{"linear_steps", s.linear_steps}, {"min_linear_steps", s.min_linear_steps},
                   {"binary_steps", s.binary_steps}, {"secant", s.secant},
                   {"planar", s.planar},             {"max_crossings", s.max_crossings}};
    r["within_budget"] = choice.chosen >= 0;
    if (choice.chosen >= 0) {
        const ObjectError& e = choice.tried[size_t(choice.chosen)].error;
        r["over_budget"] = e.over_budget;
        r["p99_8bit"] = e.p99;
        r["max_8bit"] = e.max;
    } else if (!choice.tried.empty()) {
        // How near the budget the search came.
        const auto closest = std::min_element(choice.tried.begin(), choice.tried.end(), [](const auto& a, const auto& b) {
            return a.error.over_budget < b.error.over_budget;
        });
        r["closest"] = {{"setting", closest->setting.label()}, {"over_budget", closest->error.over_budget},
                        {"p99_8bit", closest->error.p99}, {"max_8bit", closest->error.max}};
    }
    const auto error = [](const ObjectError& e) {
        return nlohmann::json{{"over_budget", e.over_budget}, {"p99_8bit", e.p99}, {"max_8bit", e.max}};
    };
    r["most_accurate"] = {{"setting", ReliefSetting{}.label()}, {"error", error(choice.most_accurate_error)}};
    if (choice.have_exact)
        r["vs_bilinear"] = {{"chosen", error(choice.exact_chosen)}, {"most_accurate", error(choice.exact_most_accurate)}};
    r["candidates_tried"] = choice.tried.size();
    r["order"] = "sweep relief's frame times at " + std::to_string(int(std::lround(choice.angle_deg))) +
                 " degrees (docs/relief-sweep/)";
    r["costs_measured_by"] = measured_costs::provenance();
    if (choice.chosen >= 0) r["sweep_ms"] = choice.tried[size_t(choice.chosen)].cost;
    r["cpu_ms"] = choice.chosen_ms;
    r["most_accurate_cpu_ms"] = choice.most_accurate_ms;
    return r;
}

}  // namespace st
