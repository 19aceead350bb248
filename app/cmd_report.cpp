// cmd_report.cpp: `report`, the main job. Scenes (every one by default) on
// both backends, compared and timed; the HTML page of report_page.h, the
// Markdown tables (summary.md, and stdout unless --brief asks for a few
// lines instead: report_summary.h), and JUnit XML on request.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/tool_data.h"
#include "app/progress.h"
#include "app/memory_budget.h"
#include "app/json_text.h"
#include "app/junit.h"
#include "app/backends.h"
#include "app/bench.h"
#include "app/commands.h"
#include "app/comparison.h"
#include "app/provenance.h"
#include "app/report/report_gallery.h"
#include "app/report/report_page.h"
#include "app/report/report_summary.h"
#include "app/report/report_techniques.h"
#include "app/short_number.h"
#include "image/image_io.h"
#include "scene/scene.h"

namespace st {

int cmd_report(const std::vector<std::string>& patterns, const ReportOptions& options, const CommonOptions& common) {
    const std::string& out_dir = options.out_dir;
    const std::string& junit_path = options.junit;
    const int frames = options.frames;
    if (!junit_path.empty()) check_junit_path(junit_path);
    std::vector<Scene> scenes;
    for (const auto& n : patterns.empty() ? builtin_scene_names() : expand_scene_patterns(patterns))
        scenes.push_back(load_scene(n, common.overrides));
    check_memory(scenes, MemoryUse::Compare, common.max_memory);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());

    set_llvmpipe_threads(common.threads);
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    std::vector<ReportEntry> entries;
    JunitReport junit("shadertwin report");
    Progress progress("report", scenes.size());
    for (const Scene& s : scenes) {
        progress.step(s.name);
        const auto start = std::chrono::steady_clock::now();
        ReportEntry e{s.name, s.kind, compare_scene(s, backends, out_dir, CompareFiles{options.exr, true}),
                      std::nullopt, s.paper, s.quality};
        add_junit_cases(junit, s, e.comparison, out_dir,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (frames > 0) {
            e.cost = bench_scene(s, backends, frames, 2);
        }
        entries.push_back(std::move(e));
    }
    // Failures first, then as given.
    std::stable_sort(entries.begin(), entries.end(),
                     [](const ReportEntry& a, const ReportEntry& b) { return !a.comparison.pass() && b.comparison.pass(); });
    const std::string renderer = backends.gl_renderer();
    const ReportHeader header{tool_name(),
                              "shadertwin " + shadertwin_version() + "; reference: " + renderer + "; Mesa " +
                                  mesa_version(backends.gl_version()) + "; CPU flags: " + cpu_flags() +
                                  (frames > 0 ? "; " + std::to_string(frames) + " timed frames per backend, interleaved"
                                              : std::string()),
                              out_dir, frames};
    const std::vector<SweepChart> charts = copy_sweep_charts(techniques_in_order(entries), out_dir);
    write_text_file(out_dir + "/index.html",
                    report_page(header, entries, technique_section(entries, charts), report_gallery(entries)));
    const std::string markdown = report_markdown(entries, renderer, frames);
    write_text_file(out_dir + "/summary.md", markdown);
    std::cout << (options.brief ? report_brief(entries, out_dir) : markdown);
    if (!junit_path.empty()) write_junit(junit_path, junit);
    const bool all_pass = std::all_of(entries.begin(), entries.end(), [](auto& e) { return e.comparison.pass(); });
    return all_pass ? 0 : 1;
}

}  // namespace st
