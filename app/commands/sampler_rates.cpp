// sampler_rates.cpp: see sampler_rates.h.
#include "app/commands/sampler_rates.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/backends.h"
#include "app/bench.h"
#include "app/json_text.h"
#include "app/progress.h"
#include "app/tool_data.h"
#include "image/compare.h"
#include "scene/scene.h"

namespace st {

namespace {

constexpr int kSize = 512;

struct Entry {
    const char* name;
    const char* fragment;
    bool cube;
    nlohmann::json uniforms;
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> all = {
        {"texture", "sample_implicit", false, nlohmann::json::array()},
        {"textureLod", "sample_lod", false, {{{"name", "lod_min"}, {"float", 0.0}}, {{"name", "lod_max"}, {"float", 3.0}}}},
        {"textureGrad", "sample_grad", false, {{{"name", "grad_scale"}, {"float", 1.5}}}},
        {"cube texture", "sample_cube", true, nlohmann::json::array()},
        {"cube textureLod", "sample_cube_lod", true,
         {{{"name", "lod_min"}, {"float", 0.0}}, {{"name", "lod_max"}, {"float", 3.0}}}},
        {"cube textureGrad", "sample_cube_grad", true, {{{"name", "grad_scale"}, {"float", 1.5}}}},
    };
    return all;
}

const Entry& entry_of(const SamplerCase& c) {
    for (const Entry& e : entries())
        if (c.entry == e.name) return e;
    throw std::invalid_argument("no sampler entry point '" + c.entry + "'");
}

// A corner of the screen-filling quad: position, colour (r and g run 0..1
// across and up: textureLod's LOD and textureGrad's scales; b turns a cube's
// direction from +z towards the sides) and uv.
nlohmann::json corner_triangle(bool cube, const int (&corners)[3][2]) {
    nlohmann::json t = {{"positions", nlohmann::json::array()}, {"colours", nlohmann::json::array()},
                        {"uvs", nlohmann::json::array()}};
    for (const auto& c : corners) {
        const double x = c[0], y = c[1];
        t["positions"].push_back({x * kSize, y * kSize});
        t["colours"].push_back({x, y, cube ? 1.0 - 0.6 * x * y : 1.0, 1.0});
        // 2D: the 256-texel map three times across, 1.5 texels a pixel (LOD
        // 0.58); cube: directions over the +z face and past its edges.
        if (cube) t["uvs"].push_back({-1.3 + 2.6 * x, -1.3 + 2.6 * y});
        else t["uvs"].push_back({3.0 * x, 3.0 * y});
    }
    return t;
}

// Pixels whose float bits differ between the two backends' images (compare's
// identical_fraction_float): a rate counts only for reads that are
// llvmpipe's to the bit.
long differing_pixels(const Image& a, const Image& b) {
    const double pixels = double(a.width) * double(a.height);
    return long(std::llround((1.0 - compare_images(a, b).identical_fraction_float) * pixels));
}

}  // namespace

std::string SamplerCase::name() const {
    std::string e = entry;
    for (char& ch : e)
        if (ch == ' ') ch = '-';
    return "sampler-rate-" + e + "-" + format + "-" + filter;
}

std::vector<SamplerCase> sampler_cases() {
    std::vector<SamplerCase> cases;
    const char* filters[] = {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_linear"};
    for (const Entry& e : entries()) {
        std::vector<std::string> formats = {"rgba8", "rgba16f", "rgba32f", "r32f"};
        if (!e.cube) formats.insert(formats.begin() + 1, "srgb8_alpha8");  // 2D only
        for (const std::string& f : formats)
            for (const char* filter : filters) cases.push_back({e.name, f, filter});
    }
    return cases;
}

nlohmann::json sampler_case_document(const SamplerCase& c) {
    const Entry& e = entry_of(c);
    const bool mips = c.filter.find("mipmap") != std::string::npos;
    const bool linear = c.filter == "linear" || c.filter == "linear_mipmap_linear";
    nlohmann::json texture = {{"sampler", e.cube ? "env" : "tex"},
                              {"format", c.format},
                              {"min_filter", c.filter},
                              {"mag_filter", linear ? "linear" : "nearest"},
                              {"wrap", e.cube ? "clamp" : "repeat"},
                              {"width", e.cube ? 128 : 256},
                              {"height", e.cube ? 128 : 256},
                              {"pattern", "noise"},
                              {"seed", 5},
                              {"mipmaps", mips ? "box" : "none"}};
    if (e.cube) texture["cube"] = true;
    const int first[3][2] = {{0, 0}, {1, 0}, {1, 1}}, second[3][2] = {{0, 0}, {1, 1}, {0, 1}};
    return {{"kind", "conformance"},
            {"description", c.entry + " on a " + c.format + " texture, min filter " + c.filter + " (bench --samplers)"},
            {"width", kSize},
            {"height", kSize},
            {"fragment", e.fragment},
            {"uniforms", e.uniforms},
            {"textures", {texture}},
            {"triangles", {corner_triangle(e.cube, first), corner_triangle(e.cube, second)}}};
}

int cmd_bench_samplers(int frames, bool json, const CommonOptions& common) {
    set_llvmpipe_threads(common.threads);
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    const std::vector<SamplerCase> cases = sampler_cases();
    if (!json)
        std::printf("%-17s %-13s %-23s %14s %14s %7s  %s\n", "entry point", "format", "min filter", "cpu Msample/s",
                    "gl Msample/s", "cpu/gl", "bits");
    Progress progress("bench --samplers", cases.size());
    int failed = 0;
    for (const SamplerCase& c : cases) {
        progress.step(c.name());
        const Scene scene = load_scene_document(c.name(), sampler_case_document(c), "");
        const long differing =
            differing_pixels(backends.render(Backend::Cpu, scene.frame).image, backends.render(Backend::Gl, scene.frame).image);
        failed += differing != 0;
        const BenchResult r = bench_scene(scene, backends, frames, std::max(2, frames / 10));
        const double samples = double(kSize) * kSize;
        const double cpu = r.cpu.ms_median > 0 ? samples / r.cpu.ms_median / 1000.0 : 0.0;
        const double gl = r.gl.ms_median > 0 ? samples / r.gl.ms_median / 1000.0 : 0.0;
        if (json) {
            std::cout << json_text({{"entry", c.entry},
                                    {"format", c.format},
                                    {"min_filter", c.filter},
                                    {"samples_per_frame", samples},
                                    {"cpu_msamples_per_s", cpu},
                                    {"gl_msamples_per_s", gl},
                                    {"cpu_ms_median", r.cpu.ms_median},
                                    {"gl_ms_median", r.gl.ms_median},
                                    {"frames", frames},
                                    {"differing_pixels", differing}})
                      << std::endl;
            continue;
        }
        std::printf("%-17s %-13s %-23s %14.1f %14.1f %7.2f  %s\n", c.entry.c_str(), c.format.c_str(), c.filter.c_str(),
                    cpu, gl, gl > 0 ? cpu / gl : 0.0,
                    differing ? (std::to_string(differing) + " pixels differ").c_str() : "same");
        std::fflush(stdout);
    }
    if (!json)
        std::printf("%dx%d, one read a pixel; frames %d per backend (medians), cpu threads %d, LP_NUM_THREADS %s\n", kSize,
                    kSize, frames, common.threads, std::getenv("LP_NUM_THREADS") ? std::getenv("LP_NUM_THREADS") : "unset");
    return failed ? 1 : 0;
}

}  // namespace st
