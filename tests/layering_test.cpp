// layering_test.cpp: the folders depend on each other in one direction only.
// Every `#include "folder/..."` of the project's own headers must name a
// folder that the including folder may use (the table below, which is also
// the picture in docs/architecture.md). In particular the pipeline (raster/)
// and the shading runtime (shading/, texture/) never include technique code
// (kernels/, scene/), and glsl/ holds shaders only.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

namespace st {

namespace fs = std::filesystem;

namespace {

const std::map<std::string, std::set<std::string>>& allowed() {
    static const std::map<std::string, std::set<std::string>> table = {
        {"simd", {}},
        {"frame", {}},
        {"image", {}},
        {"texture", {"frame", "simd"}},
        {"shading", {"frame", "simd", "texture"}},
        {"raster", {"frame", "image", "simd", "texture", "shading"}},
        {"kernels", {"frame", "simd", "texture", "shading"}},
        {"gl", {"frame", "image"}},
        // Ground truth sits above the twins it measures, and reads their
        // textures and samplers.
        {"reference", {"frame", "simd", "texture", "shading", "kernels"}},
        {"optics", {"reference"}},
        // A scene reader asks the pipeline's setup whether the positions it
        // reads can be snapped (raster/setup_reach.h).
        {"scene", {"frame", "image", "simd", "texture", "shading", "raster", "kernels", "optics"}},
        {"app", {"frame", "image", "simd", "texture", "shading", "raster", "kernels", "gl", "scene", "reference",
                 "optics"}},
        // The SDK a user's tool builds against: the runtime twins are written
        // in, the scene kinds' reader, and the tool's command line.
        {"sdk", {"frame", "simd", "texture", "shading", "kernels", "scene", "app"}},
        // An out-of-tree technique sees what the installed package offers.
        {"examples", {"frame", "simd", "texture", "shading", "scene", "sdk"}},
        {"bench", {"frame", "image", "simd", "texture", "shading", "raster", "kernels", "gl", "scene", "app"}},
        {"tests", {"frame", "image", "simd", "texture", "shading", "raster", "kernels", "gl", "scene", "app", "sdk"}},
    };
    return table;
}

}  // namespace

TEST(Layering, IncludesPointOneWay) {
    const fs::path root(SHADERTWIN_SOURCE_DIR);
    static const std::regex include(R"(^\s*#\s*include\s+"([a-z_]+)/)");
    int checked = 0;
    for (const auto& [folder, uses] : allowed()) {
        if (!fs::exists(root / folder)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / folder)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".h" && ext != ".cpp") continue;
            std::ifstream in(e.path());
            std::string line;
            std::smatch m;
            while (std::getline(in, line)) {
                if (!std::regex_search(line, m, include)) continue;
                const std::string target = m[1];
                ++checked;
                if (target == folder || !allowed().count(target)) continue;
                EXPECT_TRUE(uses.count(target))
                    << fs::relative(e.path(), root) << " includes " << target << "/ against the layering";
            }
        }
    }
    EXPECT_GT(checked, 100);
}

// glsl/ holds shaders only: no host code beside them.
TEST(Layering, GlslHoldsShadersOnly) {
    for (const auto& e : fs::recursive_directory_iterator(fs::path(SHADERTWIN_SOURCE_DIR) / "glsl")) {
        if (!e.is_regular_file()) continue;
        const std::string ext = e.path().extension().string();
        EXPECT_TRUE(ext == ".vert" || ext == ".frag" || ext == ".glsl") << e.path() << " is not a shader";
    }
}

}  // namespace st
