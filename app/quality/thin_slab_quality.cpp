// thin_slab_quality.cpp: `quality: auto` for thin-slab scenes (thin_slab_quality.h).
#include "app/quality/thin_slab_quality.h"

#include "app/quality/thin_slab_exact.h"
#include "raster/cpu_renderer.h"
#include "scene/scene.h"

namespace st {

namespace {

constexpr const char* kCostOrder[] = {"vertex", "host", "fragment"};


}  // namespace

double thin_slab_quality_budget(const nlohmann::json& document) {
    return read_quality_budget(document, "the cheapest evaluation");
}

nlohmann::json with_thin_slab_variant(const nlohmann::json& document, const std::string& variant) {
    nlohmann::json d = without_quality_fields(document);
    d["variant"] = variant;
    return d;
}

ThinSlabQualityChoice measure_thin_slab_quality(const TwinLibrary& twins, int threads, const std::string& name,
                                                const nlohmann::json& document, int frames) {
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
    for (const char* variant : kCostOrder) {
        const Scene scene = load_scene_document(name, with_thin_slab_variant(document, variant), "");
        ThinSlabCandidate c{variant, object_error(renderer.render(scene.frame), reference, choice.budget)};
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
                        {"cpu_ms", choice.chosen_ms},
                        {"most_accurate_cpu_ms", choice.most_accurate_ms}};
    nlohmann::json tried = nlohmann::json::array();
    for (const ThinSlabCandidate& c : choice.tried)
        tried.push_back({{"variant", c.variant}, {"over_budget", c.error.over_budget}, {"p99_8bit", c.error.p99},
                         {"max_8bit", c.error.max}});
    r["tried"] = tried;
    const ThinSlabCandidate* shown = choice.chosen >= 0 ? &choice.tried[size_t(choice.chosen)]
                                                        : (choice.tried.empty() ? nullptr : &choice.tried.back());
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
