// thin_slab_quality.cpp: `quality: auto` for thin-slab scenes (thin_slab_quality.h).
#include "app/quality/thin_slab_quality.h"

#include <algorithm>
#include <cmath>

#include "app/quality/thin_slab_exact.h"
#include "raster/cpu_renderer.h"
#include "scene/scene.h"

namespace st {

namespace {

// The candidates; at equal measured cost, this order.
constexpr const char* kVariants[] = {"vertex", "host", "fragment"};

// The flag's quads: half its triangles (the thin-slab draws').
int quads_of(const Frame& frame) {
    size_t triangles = 0;
    for (const Pass& pass : frame.passes)
        for (const DrawCall& d : pass.draws)
            if (d.fragment == "thin_slab") triangles += d.indices.size() / 3;
    return int(std::min<size_t>(triangles / 2, size_t(1) << 30));
}

}  // namespace

std::vector<std::pair<std::string, double>> thin_slab_cost_order(int quads, const ThinSlabCost& cost) {
    std::vector<std::pair<std::string, double>> out;
    for (const char* v : kVariants) out.emplace_back(v, cost(v, quads));
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    return out;
}

double thin_slab_quality_budget(const nlohmann::json& document) {
    return read_quality_budget(document, "the cheapest evaluation");
}

nlohmann::json with_thin_slab_variant(const nlohmann::json& document, const std::string& variant) {
    nlohmann::json d = without_quality_fields(document);
    d["variant"] = variant;
    return d;
}

ThinSlabQualityChoice measure_thin_slab_quality(const TwinLibrary& twins, int threads, const std::string& name,
                                                const nlohmann::json& document, int frames,
                                                const ThinSlabCost& cost) {
    ThinSlabQualityChoice choice;
    choice.scene = name;
    choice.budget = thin_slab_quality_budget(document);
    CpuRenderer renderer(threads, twins);
    const Scene fragment = load_scene_document(name, with_thin_slab_variant(document, "fragment"), "");
    Frame exact = fragment.frame;
    for (Pass& pass : exact.passes)
        for (DrawCall& d : pass.draws)
            if (d.fragment == "thin_slab") d.fragment = ThinSlabExactTwins::kExactThinSlab;
    const Image reference = renderer.render(exact);
    choice.quads = quads_of(fragment.frame);
    for (const auto& [variant, ms] : thin_slab_cost_order(choice.quads, cost)) {
        const Scene scene = load_scene_document(name, with_thin_slab_variant(document, variant), "");
        ThinSlabCandidate c{variant, object_error(renderer.render(scene.frame), reference, choice.budget), ms};
        choice.tried.push_back(c);
        if (c.error.within()) {
            choice.chosen = int(choice.tried.size()) - 1;
            break;
        }
    }
    const Scene chosen = load_scene_document(name, with_thin_slab_variant(document, choice.variant()), "");
    choice.chosen_ms = median_frame_ms(renderer, chosen.frame, frames);
    choice.most_accurate_ms = median_frame_ms(renderer, fragment.frame, frames);
    return choice;
}

nlohmann::json thin_slab_choice_record(const ThinSlabQualityChoice& choice) {
    nlohmann::json r = {{"technique", "thin-slab"},
                        {"budget", choice.budget},
                        {"reference", "the fragment variant in exact (double) arithmetic"},
                        {"setting", choice.variant()},
                        {"fields", {{"variant", choice.variant()}}},
                        {"within_budget", choice.chosen >= 0},
                        {"candidates_tried", choice.tried.size()},
                        {"order", "sweep thin-slab's frame times at the nearest mesh to " +
                                      std::to_string(choice.quads) + " quads (docs/thin-slab-speed/)"},
                        {"costs_measured_by", measured_costs::provenance()},
                        {"cpu_ms", choice.chosen_ms},
                        {"most_accurate_cpu_ms", choice.most_accurate_ms}};
    nlohmann::json tried = nlohmann::json::array();
    for (const ThinSlabCandidate& c : choice.tried)
        tried.push_back({{"variant", c.variant}, {"over_budget", c.error.over_budget}, {"p99_8bit", c.error.p99},
                         {"max_8bit", c.error.max}, {"sweep_ms", c.sweep_ms}});
    r["tried"] = tried;
    // The chosen candidate, or where none is within the closest one.
    const ThinSlabCandidate* shown = choice.chosen >= 0 ? &choice.tried[size_t(choice.chosen)] : nullptr;
    for (const ThinSlabCandidate& c : choice.tried)
        if (choice.chosen < 0 && (!shown || c.error.over_budget < shown->error.over_budget)) shown = &c;
    if (shown && choice.chosen >= 0) {
        r["over_budget"] = shown->error.over_budget;
        r["p99_8bit"] = shown->error.p99;
        r["max_8bit"] = shown->error.max;
    } else if (shown) {
        r["closest"] = {{"setting", shown->variant}, {"over_budget", shown->error.over_budget},
                        {"p99_8bit", shown->error.p99}, {"max_8bit", shown->error.max}};
    }
    return r;
}

}  // namespace st
