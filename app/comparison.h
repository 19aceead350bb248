// comparison.h: one scene on both backends, its coverage pass on both, the
// metrics against the scene's criteria, and the files written for it.
// Shared by `compare` and `report`.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/backends.h"
#include "app/junit.h"
#include "image/compare.h"
#include "scene/scene.h"

namespace st {

// A named output (a render target's level) compared on both backends.
struct OutputComparison {
    std::string name;
    CompareMetrics metrics;
    std::vector<std::string> failures;
    std::string cpu_hash, gl_hash;
    std::string cpu_png, gl_png, diff_png;
};

struct SceneComparison {
    std::string scene;
    CompareMetrics metrics;
    long coverage_mismatch = 0;
    long over_1lsb = 0;             // pixels with a channel more than 1 LSB apart
    long condition_pixels = -1;     // pixels the condition map marks; -1: no map
    long explained = 0;             // of over_1lsb, those the map marks
    std::vector<std::string> failures;  // empty = pass
    double cpu_ms = 0, gl_ms = 0;
    std::string cpu_hash, gl_hash;
    // File names relative to the output folder.
    std::string cpu_png, gl_png, diff_png, coverage_diff_png, condition_png;
    std::vector<OutputComparison> outputs;  // the scene's criteria apply to each
    bool pass() const {
        for (const auto& o : outputs)
            if (!o.failures.empty()) return false;
        return failures.empty();
    }
};

// What compare_scene writes beside its verdict. `compare` keeps everything;
// `report` keeps a passing run's folder small: the float images
// (<scene>.<backend>.exr, and each named output's) of failing scenes only,
// and no second PNG where llvmpipe's image is the CPU's to the bit (its
// gl_png then names the CPU's file).
struct CompareFiles {
    bool every_exr = true;
    bool share_identical_png = false;
};
SceneComparison compare_scene(const Scene& scene, Backends& backends, const std::string& out_dir,
                              CompareFiles files = {});

nlohmann::json to_json(const SceneComparison& c);
// The scene's JUnit cases (app/junit.h): the scene and each named output,
// failures with the heat map's path and the command that reproduces them.
void add_junit_cases(JunitReport& junit, const Scene& scene, const SceneComparison& c, const std::string& out_dir,
                     double seconds);
// The metrics as a JSON object (also used by `diff`).
nlohmann::json metrics_json(const CompareMetrics& m);

// Writes `<dir>/<scene>.<backend>.png` and, with `exr`, `.exr`; returns the PNG's name.
std::string write_rendered(const std::string& dir, const std::string& scene, Backend backend,
                           const Image& image, Backends& backends, bool exr = true);

}  // namespace st
