// cmd_report.cpp: `report`, the main job. Every built-in scene on both
// backends, compared; a Markdown summary on stdout and an HTML page with the
// images, heat maps and metrics, failing scenes first.
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
#include "app/short_number.h"
#include "image/image_io.h"
#include "scene/scene.h"

namespace st {

namespace {


std::string fixed(double v, int decimals) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(decimals) << v;
    return s.str();
}

std::string html_escape(const std::string& in) {
    std::string out;
    for (char ch : in) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += ch;
        }
    }
    return out;
}

std::string cost_markdown(const std::vector<BenchResult>& costs, int frames) {
    std::ostringstream md;
    if (costs.empty()) return "";
    md << "\n## Cost\n\nFrames per second from the median of " << frames
       << " frames per backend, backends interleaved (`shadertwin bench` rules); CPU threads "
       << costs.front().cpu_threads << ", LP_NUM_THREADS " << costs.front().gl_threads
       << ". CPU stage medians in ms.\n\n"
       << "| scene | size | cpu fps | gl fps | cpu / gl | vertex | setup/binning | raster | fragment | blend/output |\n"
       << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& r : costs)
        md << "| " << r.scene << " | " << r.width << "x" << r.height << " | " << fixed(r.cpu.fps(), 1) << " | "
           << fixed(r.gl.fps(), 1) << " | " << fixed(r.cpu.fps() / r.gl.fps(), 2) << " | " << short_number(r.cpu_stages.vertex_ms, 3)
           << " | " << short_number(r.cpu_stages.setup_ms, 3) << " | " << short_number(r.cpu_stages.raster_ms, 3) << " | "
           << short_number(r.cpu_stages.fragment_ms, 3) << " | " << short_number(r.cpu_stages.output_ms, 3) << " |\n";
    return md.str();
}

std::string markdown(const std::vector<SceneComparison>& results, const std::string& renderer) {
    std::ostringstream md;
    const auto failed = std::count_if(results.begin(), results.end(), [](auto& c) { return !c.pass(); });
    md << "# shadertwin report\n\n"
       << "shadertwin " << shadertwin_version() << "; reference: " << renderer << "; CPU flags: "
       << cpu_flags() << "\n\n"
       << results.size() - failed << " of " << results.size() << " scenes pass.\n\n"
       << "| scene | result | coverage_mismatch | identical 8-bit | max_diff_8bit | identical float "
          "| max_rel_diff_float | cpu ms | gl ms |\n"
       << "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& c : results)
        md << "| " << c.scene << " | " << (c.pass() ? "pass" : "**FAIL**") << " | " << c.coverage_mismatch
           << " | " << short_number(c.metrics.identical_fraction_8bit, 6) << " | " << c.metrics.max_diff_8bit << " | "
           << short_number(c.metrics.identical_fraction_float, 6) << " | " << short_number(c.metrics.max_rel_diff_float, 3)
           << " | " << short_number(c.cpu_ms, 3) << " | " << short_number(c.gl_ms, 3) << " |\n";
    for (const auto& c : results)
        for (const auto& f : c.failures) md << "\n- " << c.scene << ": " << f;
    md << "\n";
    return md.str();
}

// The cost table goes in as preformatted Markdown: readable as it is.
std::string html(const std::vector<SceneComparison>& results, const std::string& renderer, const std::string& cost) {
    std::ostringstream h;
    h << "<!doctype html><html><head><meta charset=\"utf-8\"><title>shadertwin report</title><style>"
         "body{font-family:sans-serif;margin:2em}section{border-top:1px solid #ccc;padding:1em 0}"
         "img{image-rendering:pixelated;width:256px;border:1px solid #888;margin-right:8px}"
         ".fail{color:#b00}.pass{color:#070}td,th{padding:2px 8px;text-align:left}"
         "</style></head><body><h1>shadertwin report</h1><p>shadertwin "
      << html_escape(shadertwin_version()) << "; reference: " << html_escape(renderer)
      << "; CPU flags: " << html_escape(cpu_flags())
      << "</p><p>Heat maps: black = bit-identical floats, dark blue = floats differ but 8-bit "
         "equal, green = 1 LSB, yellow = 2-3 LSB, red = 4+ LSB, white = non-finite.</p>";
    for (const auto& c : results) {
        h << "<section><h2>" << html_escape(c.scene) << " <span class=\"" << (c.pass() ? "pass\">pass" : "fail\">FAIL")
          << "</span></h2>";
        for (const auto& f : c.failures) h << "<p class=\"fail\">" << html_escape(f) << "</p>";
        h << "<div><figure style=\"display:inline-block\"><img src=\"" << c.cpu_png
          << "\"><figcaption>cpu</figcaption></figure><figure style=\"display:inline-block\"><img src=\""
          << c.gl_png << "\"><figcaption>gl (llvmpipe)</figcaption></figure>"
          << "<figure style=\"display:inline-block\"><img src=\"" << c.diff_png
          << "\"><figcaption>difference</figcaption></figure><figure style=\"display:inline-block\"><img src=\""
          << c.coverage_diff_png << "\"><figcaption>coverage difference</figcaption></figure></div><table>";
        const nlohmann::json j = to_json(c);
        for (const auto& [key, value] : j.items())
            if (key != "failures" && key != "scene" && key != "outputs")
                h << "<tr><th>" << html_escape(key) << "</th><td>" << html_escape(json_text(value)) << "</td></tr>";
        h << "</table>";
        // Each named output (a render target's level) as the image is shown.
        for (const auto& o : c.outputs) {
            h << "<h3>" << html_escape(o.name) << " <span class=\""
              << (o.failures.empty() ? "pass\">pass" : "fail\">FAIL") << "</span></h3>";
            for (const auto& f : o.failures) h << "<p class=\"fail\">" << html_escape(f) << "</p>";
            h << "<div><figure style=\"display:inline-block\"><img src=\"" << o.cpu_png
              << "\"><figcaption>cpu</figcaption></figure><figure style=\"display:inline-block\"><img src=\""
              << o.gl_png << "\"><figcaption>gl (llvmpipe)</figcaption></figure><figure style=\"display:inline-block\">"
              << "<img src=\"" << o.diff_png << "\"><figcaption>difference</figcaption></figure></div>"
              << "<p>identical_fraction_float " << o.metrics.identical_fraction_float << ", max_diff_8bit "
              << o.metrics.max_diff_8bit << ", max_rel_diff_float " << o.metrics.max_rel_diff_float << "</p>";
        }
        h << "</section>";
    }
    if (!cost.empty()) h << "<section><h2>Cost</h2><pre>" << html_escape(cost) << "</pre></section>";
    h << "</body></html>\n";
    return h.str();
}

}  // namespace

int cmd_report(const std::vector<std::string>& patterns, const std::string& out_dir, int frames,
               const std::string& junit_path, const CommonOptions& common) {
    if (!junit_path.empty()) check_junit_path(junit_path);
    std::vector<Scene> scenes;
    for (const auto& n : patterns.empty() ? builtin_scene_names() : expand_scene_patterns(patterns))
        scenes.push_back(load_scene(n, common.overrides));
    check_memory(scenes, MemoryUse::Compare, common.max_memory);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());

    set_llvmpipe_threads(common.threads);
    Backends backends(common.threads, glsl_roots());
    std::vector<SceneComparison> results;
    std::vector<BenchResult> costs;
    JunitReport junit("shadertwin report");
    Progress progress("report", scenes.size());
    for (const Scene& s : scenes) {
        progress.step(s.name);
        const auto start = std::chrono::steady_clock::now();
        results.push_back(compare_scene(s, backends, out_dir));
        add_junit_cases(junit, s, results.back(), out_dir,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (frames > 0) costs.push_back(bench_scene(s, backends, frames, 2));
    }
    // Failures first, then by name.
    std::stable_sort(results.begin(), results.end(),
                     [](const SceneComparison& a, const SceneComparison& b) { return !a.pass() && b.pass(); });
    const std::string renderer = backends.gl_renderer();
    const std::string cost = cost_markdown(costs, frames);
    write_text_file(out_dir + "/index.html", html(results, renderer, cost));
    std::cout << markdown(results, renderer) << cost;
    if (!junit_path.empty()) write_junit(junit_path, junit);
    const bool all_pass = std::all_of(results.begin(), results.end(), [](auto& c) { return c.pass(); });
    return all_pass ? 0 : 1;
}

}  // namespace st
