// cmd_golden.cpp: `golden check|update`. Goldens are the CPU backend's
// hashes, committed in tests/golden/hashes.json for the built-in scenes (a
// user technique keeps its own file); they change only through
// `golden update`.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/tool_data.h"
#include "app/memory_budget.h"
#include "app/json_text.h"
#include "app/backends.h"
#include "app/commands.h"
#include "app/junit.h"
#include "image/image_io.h"
#include "scene/scene.h"

namespace st {

int cmd_golden(const std::string& action, const std::vector<std::string>& names_in, const std::string& junit_path,
               const CommonOptions& common) {
    if (!junit_path.empty()) check_junit_path(junit_path);
    const std::vector<std::string> names = names_in.empty() ? builtin_scene_names() : names_in;
    std::vector<Scene> scenes;
    for (const auto& n : names) scenes.push_back(load_scene(n, common.overrides));
    check_memory(scenes, MemoryUse::RenderCpu, common.max_memory);

    // Each scene's hashes live in its source's golden file (scene/scene_sources.h):
    // the built-in ones in tests/golden/hashes.json, a user technique's in its own.
    std::map<std::string, nlohmann::json> goldens;
    for (const Scene& scene : scenes) {
        if (goldens.count(scene.golden_file)) continue;
        nlohmann::json& golden = goldens[scene.golden_file] = nlohmann::json::object();
        std::ifstream in(scene.golden_file);
        if (in) {
            golden = nlohmann::json::parse(in, nullptr, false);
            if (golden.is_discarded() || !golden.is_object())
                throw std::runtime_error(scene.golden_file + ": malformed JSON");
        } else if (action == "check") {
            throw std::runtime_error("no golden file at " + scene.golden_file);
        }
    }

    Backends backends(common.threads, common.gl_platform, glsl_roots());
    std::vector<std::string> changed;
    JunitReport junit("shadertwin golden " + action);
    for (const Scene& scene : scenes) {
        nlohmann::json& golden = goldens[scene.golden_file];
        const auto start = std::chrono::steady_clock::now();
        // The image under the scene's name, each named output under
        // "<scene>:<output>".
        const Rendered r = backends.render(Backend::Cpu, scene.frame);
        std::vector<std::pair<std::string, std::string>> hashes = {{scene.name, pixel_hash(r.image)}};
        for (const NamedImage& o : r.outputs) hashes.push_back({scene.name + ":" + o.name, pixel_hash(o.image)});
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string update = "update: " + tool_name() + " golden update " + scene.name;
        for (const auto& [key, hash] : hashes) {
            const bool known = golden.contains(key);
            // The scene's render time on its first case; its outputs came with it.
            JunitCase junit_case{"shadertwin." + scene.kind, key, key == scene.name ? seconds : 0.0, {}, update};
            if (action == "update") {
                if (!known || golden[key] != hash) changed.push_back(key);
                golden[key] = hash;
            } else if (!known) {
                std::cout << key << " no golden (run golden update " << scene.name << ")\n";
                junit_case.failures.push_back("no golden hash in " + scene.golden_file);
                changed.push_back(key);
            } else if (golden[key] != hash) {
                std::cout << key << " changed: golden " << golden[key].get<std::string>() << " now " << hash << "\n";
                junit_case.failures.push_back("changed: golden " + golden[key].get<std::string>() + " now " + hash);
                changed.push_back(key);
            } else {
                std::cout << key << " ok\n";
            }
            junit.add(std::move(junit_case));
        }
    }
    if (action == "update") {
        for (const auto& [file, golden] : goldens) {
            // A user technique's first update makes its golden folder.
            std::error_code ec;
            const std::filesystem::path folder = std::filesystem::path(file).parent_path();
            if (!folder.empty()) std::filesystem::create_directories(folder, ec);
            if (ec) throw std::runtime_error("cannot create folder " + folder.string() + ": " + ec.message());
            write_text_file(file, json_text(golden, 2) + "\n");
        }
        std::cout << "updated " << changed.size() << " golden hashes (" << scenes.size() << " scenes)\n";
        if (!junit_path.empty()) write_junit(junit_path, junit);
        return 0;
    }
    if (!junit_path.empty()) write_junit(junit_path, junit);
    if (!changed.empty()) {
        std::cerr << "golden check failed for:";
        for (const auto& n : changed) std::cerr << " " << n;
        std::cerr << "\n";
        return 1;
    }
    return 0;
}

}  // namespace st
