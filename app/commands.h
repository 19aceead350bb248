// commands.h: the subcommands of `shadertwin`. Each returns the process exit
// code: 0 success, 1 a check failed, 2 an error (bad input among them).
#pragma once

#include <set>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl_platform.h"
#include "image/thresholds.h"

namespace st {

struct CommonOptions {
    std::vector<std::string> overrides;  // --set PATH=VALUE
    int threads = 2;                     // --threads N
    uint64_t max_memory = 0;             // --max-memory SIZE in bytes; 0: the machine's limits only
    GlPlatform gl_platform = GlPlatform::Auto;  // --gl, else SHADERTWIN_GL, else auto
};

// SHADERTWIN_GL when set (auto, osmesa or egl), else auto. Throws
// std::invalid_argument on any other value.
GlPlatform gl_platform_from_environment();

int cmd_version(GlPlatform gl_platform);
int cmd_list();
int cmd_render(const std::vector<std::string>& scenes, const std::string& backend,
               const std::string& out_dir, const CommonOptions& common);
// `junit`: a JUnit XML file to write, or empty.
int cmd_compare(const std::vector<std::string>& scenes, const std::string& out_dir, bool json,
                const std::string& junit, const CommonOptions& common);
// Without thresholds the strict default criteria decide; with them, idiff's
// rule (image/thresholds.h). Exit 0 the same within bounds (a warning
// included), 1 they differ, 2 an error.
int cmd_diff(const std::string& a, const std::string& b, const std::string& out_png, bool json,
             const std::optional<Thresholds>& thresholds);
int cmd_golden(const std::string& action, const std::vector<std::string>& scenes, const std::string& junit,
               const CommonOptions& common);
struct ReportOptions {
    std::string out_dir;
    int frames = 10;     // timed frames per backend, 0: none
    std::string junit;   // JUnit XML file, empty: none
    bool exr = false;    // keep every scene's EXR images, not only the failing ones'
    bool brief = false;  // stdout: a few lines that say what was found, not the Markdown tables
};
// `scenes`: names, paths or patterns (scene.h); every scene when empty.
int cmd_report(const std::vector<std::string>& scenes, const ReportOptions& options, const CommonOptions& common);
int cmd_bench(const std::vector<std::string>& scenes, int frames, bool json, bool scaling, bool per_pass,
              const CommonOptions& common);
int cmd_optics_figures(const std::string& out_dir, long long photons, int threads);
int cmd_sweep(const std::string& technique, const std::string& out_dir, int frames, const CommonOptions& common);
int cmd_sweep_relief(const std::string& out_dir, int frames, const CommonOptions& common);
int cmd_sweep_profile(const std::string& scene, const std::string& out_dir, int frames, const CommonOptions& common);
// Every built-in profile scene when `scenes` is empty.
int cmd_sweep_quality(const std::vector<std::string>& scenes, const std::string& out_dir, int frames,
                      const CommonOptions& common);

// Single-layer optics options of `slab` and `profile` (see docs/optics.md).
struct SlabOptions {
    std::string model = "multipole";  // multipole | dipole | mc
    double sigma_a = -1, sigma_s = -1, g = 0, eta = 1.0, eta_below = -1;
    bool eta_below_given = false;  // else --eta-below takes --eta's value
    std::string thickness;  // mm or "inf"
    int pairs = -1;         // -1: from the tolerance
    double tolerance = 1e-6;
    std::string source = "first-scatter";  // first-scatter | paper (diffusion source depth)
    double roughness = 0;     // RMS slope of the top surface (Beckmann), 0 = smooth
    std::string layers_file;  // --layers: replaces the single-layer options
    bool no_km = false;
    bool from_below = false;  // --layers: the stack turned over
    int grid = 256;
    double extent = 0.0;
    long long photons = 1000000;  // mc
    long long seed = 1;           // mc
    int threads = 2;              // mc
    bool json = false;
    std::set<std::string> given;  // the options on the command line ("--grid"): what is not used is refused
};
int cmd_slab(const SlabOptions& options);
// The notes of the last cmd_slab or cmd_profile (options the model does not
// use), for the caller to print after the command succeeded.
std::vector<std::string> take_slab_notes();
int cmd_profile(const SlabOptions& options, const std::string& out, double r_max, int samples);

}  // namespace st
