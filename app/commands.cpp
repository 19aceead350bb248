// commands.cpp: version, list, render, compare and diff.
#include "app/commands.h"

#include <cstdlib>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/backends.h"
#include "app/comparison.h"
#include "app/json_text.h"
#include "app/junit.h"
#include "app/memory_budget.h"
#include "app/provenance.h"
#include "app/quality/quality_resolver.h"
#include "app/short_number.h"
#include "app/tool_data.h"
#include "image/image_io.h"
#include "image/thresholds.h"
#include "scene/scene.h"

namespace st {

namespace {

// Loads every scene first, and checks that each fits in memory, so that bad
// input fails before any file is written.
// `estimates` gets each scene's estimated peak memory.
std::vector<Scene> load_all(const std::vector<std::string>& names, const CommonOptions& common, MemoryUse use,
                            std::vector<uint64_t>& estimates) {
    std::vector<Scene> scenes;
    for (const auto& n : names) scenes.push_back(load_scene(n, common.overrides));
    estimates = check_memory(scenes, use, common.max_memory);
    return scenes;
}

// The estimate and the measured peak of one scene, for the JSON line.
nlohmann::json memory_json(uint64_t estimate) {
    constexpr double kMiB = 1024.0 * 1024.0;
    return {{"estimate_mb", std::round(double(estimate) / kMiB)},
            {"peak_mb", std::round(double(peak_resident_bytes()) / kMiB)}};
}

void make_dir(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + dir + ": " + ec.message());
}

void print_human(const SceneComparison& c) {
    std::cout << std::left << std::setw(28) << c.scene << (c.pass() ? " pass" : " FAIL")
              << "  coverage_mismatch " << c.coverage_mismatch << "  identical_8bit "
              << c.metrics.identical_fraction_8bit << "  max_diff_8bit " << c.metrics.max_diff_8bit
              << "  identical_float " << c.metrics.identical_fraction_float << "  max_rel_diff_float "
              << c.metrics.max_rel_diff_float;
    // NaN against NaN of other bits: shown whenever there are some, so that
    // criteria.nonfinite "nan_any_payload" never hides them.
    if (c.metrics.nan_payload_only) std::cout << "  nan_payload_only " << c.metrics.nan_payload_only;
    std::cout << "\n";
    for (const auto& f : c.failures) std::cout << "    " << f << "\n";
    for (const auto& o : c.outputs) {
        std::cout << "  " << std::left << std::setw(26) << o.name << (o.failures.empty() ? " pass" : " FAIL")
                  << "  identical_8bit " << o.metrics.identical_fraction_8bit << "  max_diff_8bit "
                  << o.metrics.max_diff_8bit << "  identical_float " << o.metrics.identical_fraction_float
                  << "  max_rel_diff_float " << o.metrics.max_rel_diff_float << "\n";
        for (const auto& f : o.failures) std::cout << "      " << f << "\n";
    }
}

}  // namespace

GlPlatform gl_platform_from_environment() {
    const char* name = std::getenv("SHADERTWIN_GL");
    if (!name || !*name) return GlPlatform::Auto;
    try {
        return parse_gl_platform(name);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("SHADERTWIN_GL: ") + e.what());
    }
}

int cmd_version(GlPlatform gl_platform) {
    Backends backends(1, gl_platform, glsl_roots());
    const std::string renderer = backends.gl_renderer(), version = backends.gl_version();
    std::cout << "shadertwin " << shadertwin_version() << "\n"
              << "mesa " << mesa_version(version) << "\n"
              << "llvm " << llvm_version(renderer) << "\n"
              << "gl_renderer " << renderer << "\n"
              << "gl_version " << version << "\n"
              << "gl_platform " << gl_platform_name(backends.gl_platform()) << "\n"
              << "cpu_flags " << cpu_flags() << "\n";
    return 0;
}

int cmd_list() {
    for (const auto& name : builtin_scene_names()) std::cout << name << "\n";
    return 0;
}

int cmd_render(const std::vector<std::string>& names, const std::string& backend_str,
               const std::string& out_dir, const CommonOptions& common) {
    const Backend backend = backend_str == "gl" ? Backend::Gl : Backend::Cpu;
    const MemoryUse use = backend == Backend::Gl ? MemoryUse::RenderGl : MemoryUse::RenderCpu;
    std::vector<uint64_t> estimates;
    const auto scenes = load_all(names, common, use, estimates);
    make_dir(out_dir);
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    for (size_t i = 0; i < scenes.size(); ++i) {
        const Scene& scene = scenes[i];
        reset_peak_resident();
        const Rendered r = backends.render(backend, scene.frame);
        write_rendered(out_dir, scene.name, backend, r.image, backends);
        nlohmann::json j = {{"scene", scene.name},  {"backend", backend_name(backend)},
                            {"width", r.image.width}, {"height", r.image.height},
                            {"hash", pixel_hash(r.image)}, {"ms", r.ms}};
        j["outputs"] = nlohmann::json::array();
        for (const NamedImage& o : r.outputs) {
            write_rendered(out_dir, scene.name + "." + o.name, backend, o.image, backends);
            j["outputs"].push_back({{"name", o.name}, {"width", o.image.width}, {"height", o.image.height},
                                    {"hash", pixel_hash(o.image)}});
        }
        if (backend == Backend::Gl) j["gl_platform"] = gl_platform_name(backends.gl_platform());
        if (backend == Backend::Cpu)
            j["stages"] = {{"vertex", r.stages.vertex_ms},       {"setup_binning", r.stages.setup_ms},
                           {"rasterization", r.stages.raster_ms}, {"fragment", r.stages.fragment_ms},
                           {"blend_output", r.stages.output_ms}};
        j["memory"] = memory_json(estimates[i]);
        if (!scene.quality.is_null()) j["quality"] = scene.quality;
        std::cout << json_text(j) << std::endl;
    }
    return 0;
}

int cmd_compare(const std::vector<std::string>& names, const std::string& out_dir, bool json,
                const std::string& junit_path, const CommonOptions& common) {
    if (!junit_path.empty()) check_junit_path(junit_path);
    std::vector<uint64_t> estimates;
    const auto scenes = load_all(names, common, MemoryUse::Compare, estimates);
    make_dir(out_dir);
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    JunitReport junit("shadertwin compare");
    bool all_pass = true;
    for (size_t i = 0; i < scenes.size(); ++i) {
        const Scene& scene = scenes[i];
        reset_peak_resident();
        const auto start = std::chrono::steady_clock::now();
        const SceneComparison c = compare_scene(scene, backends, out_dir);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        add_junit_cases(junit, scene, c, out_dir, seconds);
        all_pass &= c.pass();
        nlohmann::json j = to_json(c);
        j["memory"] = memory_json(estimates[i]);
        if (!scene.quality.is_null()) j["quality"] = scene.quality;
        if (json) {
            std::cout << json_text(j) << std::endl;
        } else {
            print_human(c);
            if (!scene.quality.is_null()) std::cout << "  " << quality_summary(scene.quality) << "\n";
        }
    }
    if (!junit_path.empty()) write_junit(junit_path, junit);
    return all_pass ? 0 : 1;
}

int cmd_diff(const std::string& a_path, const std::string& b_path, const std::string& out_png, bool json,
             const std::optional<Thresholds>& thresholds) {
    const Image a = read_image(a_path), b = read_image(b_path);
    if (a.width != b.width || a.height != b.height)
        throw std::runtime_error("images differ in size: " + a_path + " and " + b_path);
    const CompareMetrics m = compare_images(a, b);
    if (!out_png.empty()) {
        const auto heat = heat_map(a, b);
        write_png_bytes(out_png, a.width, a.height, 3, heat.data());
    }
    nlohmann::json j = metrics_json(m);
    j["a"] = a_path;
    j["b"] = b_path;
    bool pass;
    if (thresholds) {
        // idiff's rule (image/thresholds.h): a warning still passes.
        const ThresholdResult r = compare_thresholds(a, b, *thresholds);
        pass = r.verdict != Verdict::Fail;
        const auto bound = [](double v) { return std::isinf(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
        j["thresholds"] = {{"fail", thresholds->fail},           {"failpercent", thresholds->fail_percent},
                           {"hardfail", bound(thresholds->hard_fail)}, {"warn", thresholds->warn},
                           {"warnpercent", thresholds->warn_percent},  {"hardwarn", bound(thresholds->hard_warn)}};
        j["verdict"] = verdict_name(r.verdict);
        j["failing_pixels"] = r.failing;
        j["warning_pixels"] = r.warning;
        j["max_error"] = {{"value", bound(r.max_error)}, {"x", r.max_x}, {"y", r.max_y}, {"channel", r.max_channel}};
        j["failures"] = r.verdict == Verdict::Fail
                            ? std::vector<std::string>{std::to_string(r.failing) + " pixels beyond " +
                                                       short_number(thresholds->fail, 6) + ", largest error " +
                                                       short_number(r.max_error, 6)}
                            : std::vector<std::string>{};
    } else {
        // Without a scene or thresholds there are only the strict default criteria to check.
        const auto failures = Criteria{}.failures(m, 0);
        pass = failures.empty();
        j["failures"] = failures;
    }
    j["pass"] = pass;
    if (json) {
        std::cout << json_text(j) << std::endl;
    } else {
        for (const auto& [key, value] : j.items()) std::cout << key << " " << json_text(value) << "\n";
    }
    return pass ? 0 : 1;
}

}  // namespace st
