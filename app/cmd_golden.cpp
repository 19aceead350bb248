// cmd_golden.cpp: `golden check|update`. Goldens are the CPU backend's
// hashes, committed in tests/golden/hashes.json; they change only through
// `golden update`.
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/backends.h"
#include "app/commands.h"
#include "image/image_io.h"
#include "scene/scene.h"

namespace st {

int cmd_golden(const std::string& action, const std::vector<std::string>& names_in,
               const CommonOptions& common) {
    const std::vector<std::string> names = names_in.empty() ? builtin_scene_names() : names_in;
    std::vector<Scene> scenes;
    for (const auto& n : names) scenes.push_back(load_scene(n, common.overrides));

    nlohmann::json golden = nlohmann::json::object();
    {
        std::ifstream in(golden_file());
        if (in) {
            golden = nlohmann::json::parse(in, nullptr, false);
            if (golden.is_discarded() || !golden.is_object())
                throw std::runtime_error(golden_file() + ": malformed JSON");
        } else if (action == "check") {
            throw std::runtime_error("no golden file at " + golden_file());
        }
    }

    Backends backends(common.threads, glsl_dir());
    std::vector<std::string> changed;
    for (const Scene& scene : scenes) {
        const std::string hash = pixel_hash(backends.render(Backend::Cpu, scene.frame).image);
        const bool known = golden.contains(scene.name);
        if (action == "update") {
            if (!known || golden[scene.name] != hash) changed.push_back(scene.name);
            golden[scene.name] = hash;
            continue;
        }
        if (!known) {
            std::cout << scene.name << " no golden (run golden update " << scene.name << ")\n";
            changed.push_back(scene.name);
        } else if (golden[scene.name] != hash) {
            std::cout << scene.name << " changed: golden " << golden[scene.name].get<std::string>()
                      << " now " << hash << "\n";
            changed.push_back(scene.name);
        } else {
            std::cout << scene.name << " ok\n";
        }
    }
    if (action == "update") {
        write_text_file(golden_file(), golden.dump(2) + "\n");
        std::cout << "updated " << changed.size() << " of " << scenes.size() << " golden hashes\n";
        return 0;
    }
    if (!changed.empty()) {
        std::cerr << "golden check failed for:";
        for (const auto& n : changed) std::cerr << " " << n;
        std::cerr << "\n";
        return 1;
    }
    return 0;
}

}  // namespace st
