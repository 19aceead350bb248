// scene_load_bench.cpp: the time to load a scene file before anything
// renders, per triangle, from 10^3 to 10^6 triangles (issue 25). Loading
// must cost time in proportion to the file: the per-triangle time should be
// flat across the range (it was quadratic while the nesting bound used
// nlohmann's parse callback). Run:
//   build/bench/microbench --benchmark_filter='LoadTriangles|ReadMeshFile'
// The same for a profile scene's OBJ mesh. A triangles scene of n pixel-space triangles, each with three vertex
// colours, written once per size into the temporary folder.
#include <benchmark/benchmark.h>

#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/mesh_file.h"
#include "scene/scene.h"

namespace {

std::string triangle_scene(int64_t n) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("shadertwin-load-bench-" + std::to_string(n) + ".json")).string();
    if (std::filesystem::exists(path)) return path;
    const std::string partial = path + ".partial";
    {
        std::ofstream out(partial);
        out << "{\"kind\": \"triangles\", \"width\": 256, \"height\": 256, \"coordinates\": \"pixels\",\n"
               " \"triangles\": [\n";
        char line[256];
        for (int64_t i = 0; i < n; ++i) {
            const double x = double(i % 250), y = double((i / 250) % 250);
            std::snprintf(line, sizeof line,
                          "  {\"positions\": [[%.3f, %.3f], [%.3f, %.3f], [%.3f, %.3f]],"
                          " \"colours\": [[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]]}%s\n",
                          x + 0.25, y + 0.5, x + 5.75, y + 1.25, x + 2.5, y + 5.5, i + 1 < n ? "," : "");
            out << line;
        }
        out << " ]}\n";
    }
    std::filesystem::rename(partial, path);
    return path;
}

// Times `load` of `path`, n triangles, per triangle.
template <class Load> void time_loads(benchmark::State& state, const std::string& path, int64_t n, Load load) {
    for (auto _ : state) {
        // Every load starts from a heap given back to the system, as the
        // tool's one load per process does: without this, the small sizes'
        // repeated loads reuse pages the first one faulted in, and the
        // comparison across sizes is of warm against cold memory.
        state.PauseTiming();
        malloc_trim(0);
        state.ResumeTiming();
        load();
    }
    // Seconds per triangle (the figure that must stay flat), and the file size.
    state.counters["per_triangle"] =
        benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["MB"] = double(std::filesystem::file_size(path)) / 1e6;
}

void BM_LoadTriangles(benchmark::State& state) {
    const std::string path = triangle_scene(state.range(0));
    time_loads(state, path, state.range(0), [&] {
        st::Scene scene = st::load_scene(path, {});
        benchmark::DoNotOptimize(scene.frame);
    });
}
BENCHMARK(BM_LoadTriangles)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

// A Wavefront OBJ mesh of n triangles (a profile scene's geometry.mesh_file):
// a grid of shared v/vt/vn corners, two triangles a cell.
std::string obj_mesh(int64_t n) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("shadertwin-load-bench-" + std::to_string(n) + ".obj")).string();
    if (std::filesystem::exists(path)) return path;
    const int64_t cells = (n + 1) / 2, side = int64_t(std::ceil(std::sqrt(double(cells))));
    const std::string partial = path + ".partial";
    {
        std::ofstream out(partial);
        char line[128];
        for (int64_t j = 0; j <= side; ++j)
            for (int64_t i = 0; i <= side; ++i) {
                const double u = double(i) / double(side), v = double(j) / double(side);
                std::snprintf(line, sizeof line, "v %.6f %.6f 0\nvt %.6f %.6f\n", u, v, u, v);
                out << line;
            }
        out << "vn 0 0 1\n";
        int64_t written = 0;
        for (int64_t j = 0; j < side && written < n; ++j)
            for (int64_t i = 0; i < side && written < n; ++i) {
                const int64_t a = j * (side + 1) + i + 1, b = a + 1, c = a + side + 2, d = a + side + 1;
                std::snprintf(line, sizeof line, "f %lld/%lld/1 %lld/%lld/1 %lld/%lld/1\n", (long long)a, (long long)a,
                              (long long)b, (long long)b, (long long)c, (long long)c);
                out << line;
                if (++written == n) break;
                std::snprintf(line, sizeof line, "f %lld/%lld/1 %lld/%lld/1 %lld/%lld/1\n", (long long)a, (long long)a,
                              (long long)c, (long long)c, (long long)d, (long long)d);
                out << line;
                ++written;
            }
    }
    std::filesystem::rename(partial, path);
    return path;
}

void BM_ReadMeshFile(benchmark::State& state) {
    const std::string path = obj_mesh(state.range(0));
    time_loads(state, path, state.range(0), [&] {
        st::ProfileMesh mesh = st::read_mesh_file(path, "geometry.mesh_file");
        benchmark::DoNotOptimize(mesh.indices);
    });
}
BENCHMARK(BM_ReadMeshFile)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
