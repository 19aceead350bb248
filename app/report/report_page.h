// report_page.h: the HTML page of `report` (index.html), one folder that
// works offline: the gallery first (report_gallery.h), then a summary table
// (failures first), each scene's
// detail folded under it with the CPU and llvmpipe images, heat map and
// condition map at a size that shows pixels, a wipe and flip between CPU and
// llvmpipe, real tables of metrics and costs, and the commands that
// reproduce the scene and update its golden hash.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/bench.h"
#include "app/comparison.h"
#include "scene/scene.h"

namespace st {

struct ReportEntry {
    std::string scene, kind;
    SceneComparison comparison;
    std::optional<BenchResult> cost;  // when report timed frames
    std::optional<PaperTiming> paper;  // the paper's frame rate for this scene, if it gave one
    nlohmann::json quality;            // what `quality: auto` chose (Scene::quality), null if not asked
};

struct ReportHeader {
    std::string tool;       // the command users call (tool_data.h)
    std::string provenance; // versions, renderer, CPU flags
    std::string out_dir;    // as given, for the commands shown
    int frames = 0;         // timed frames per backend, 0: none
};

// The entries' techniques (scene kinds), each once, in the order the
// entries first name them.
std::vector<std::string> techniques_in_order(const std::vector<ReportEntry>& entries);

// `entries` in the order shown: failures first. `gallery`: the thumbnails
// (report_gallery.h), placed first; `techniques`: the per-technique section
// (report_techniques.h), placed after the summary.
std::string report_page(const ReportHeader& header, const std::vector<ReportEntry>& entries,
                        const std::string& techniques = "", const std::string& gallery = "");

}  // namespace st
