// lane_hashes.cpp: renders every built-in scene on the CPU pipeline and
// prints "<scene> <pixel hash>" per line, and "<scene>:<output> <hash>" for
// each level of each named render target, after a first line naming this
// build's lane width. Only the CPU side is linked (no GL, no app), so
// tests/lane_width_test.sh can build it cheaply for every lane width and
// compare the hashes with tests/golden/hashes.json.
#include <iostream>
#include <string>

#include "image/image.h"
#include "kernels/registry.h"
#include "raster/cpu_renderer.h"
#include "scene/scene.h"
#include "simd/lanes.h"

int main(int argc, char** argv) {
    const int threads = argc > 1 ? std::stoi(argv[1]) : 2;
    std::cout << "lanes " << st::simd::kLanes << "\n";
    st::CpuRenderer cpu(threads, st::twins());
    for (const std::string& name : st::builtin_scene_names()) {
        const st::Scene scene = st::load_scene(name, {});
        std::cout << name << " " << st::pixel_hash(cpu.render(scene.frame)) << "\n";
        for (const st::RenderTarget& t : scene.frame.targets)
            for (int level = 0; level < t.levels; ++level)
                std::cout << name << ":" << t.name << (level ? "@" + std::to_string(level) : "") << " "
                          << st::pixel_hash(cpu.read_back(t.name, level)) << "\n";
    }
    return 0;
}
