// report_summary.cpp: see report_summary.h.
#include "app/report/report_summary.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "app/provenance.h"
#include "app/short_number.h"

namespace st {

namespace {

std::string fixed(double v, int decimals) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(decimals) << v;
    return s.str();
}

double fps_ratio(const BenchResult& r) { return r.gl.fps() > 0 ? r.cpu.fps() / r.gl.fps() : 0.0; }

}  // namespace

std::string report_markdown(const std::vector<ReportEntry>& entries, const std::string& renderer, int frames) {
    std::ostringstream md;
    const auto failed = std::count_if(entries.begin(), entries.end(), [](auto& e) { return !e.comparison.pass(); });
    md << "# shadertwin report\n\n"
       << "shadertwin " << shadertwin_version() << "; reference: " << renderer << "; CPU flags: " << cpu_flags()
       << "\n\n"
       << entries.size() - size_t(failed) << " of " << entries.size() << " scenes pass.\n\n"
       << "| scene | result | coverage_mismatch | identical 8-bit | max_diff_8bit | identical float "
          "| max_rel_diff_float | cpu ms | gl ms |\n"
       << "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& e : entries) {
        const SceneComparison& c = e.comparison;
        md << "| " << c.scene << " | " << (c.pass() ? "pass" : "**FAIL**") << " | " << c.coverage_mismatch << " | "
           << short_number(c.metrics.identical_fraction_8bit, 6) << " | " << c.metrics.max_diff_8bit << " | "
           << short_number(c.metrics.identical_fraction_float, 6) << " | "
           << short_number(c.metrics.max_rel_diff_float, 3) << " | " << short_number(c.cpu_ms, 3) << " | "
           << short_number(c.gl_ms, 3) << " |\n";
    }
    for (const auto& e : entries)
        for (const auto& f : e.comparison.failures) md << "\n- " << e.scene << ": " << f;
    md << "\n";
    const bool timed = std::any_of(entries.begin(), entries.end(), [](auto& e) { return e.cost.has_value(); });
    if (!timed) return md.str();
    const BenchResult& first = *std::find_if(entries.begin(), entries.end(), [](auto& e) { return e.cost.has_value(); })->cost;
    md << "\n## Cost\n\nFrames per second from the median of " << frames
       << " frames per backend, backends interleaved (`shadertwin bench` rules); CPU threads " << first.cpu_threads
       << ", LP_NUM_THREADS " << first.gl_threads << ". CPU stage medians in ms.\n\n"
       << "| scene | size | cpu fps | gl fps | cpu / gl | vertex | setup/binning | raster | fragment | blend/output |\n"
       << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& e : entries) {
        if (!e.cost) continue;
        const BenchResult& r = *e.cost;
        md << "| " << r.scene << " | " << r.width << "x" << r.height << " | " << fixed(r.cpu.fps(), 1) << " | "
           << fixed(r.gl.fps(), 1) << " | " << fixed(fps_ratio(r), 2) << " | " << short_number(r.cpu_stages.vertex_ms, 3)
           << " | " << short_number(r.cpu_stages.setup_ms, 3) << " | " << short_number(r.cpu_stages.raster_ms, 3)
           << " | " << short_number(r.cpu_stages.fragment_ms, 3) << " | " << short_number(r.cpu_stages.output_ms, 3)
           << " |\n";
    }
    return md.str();
}

std::string report_brief(const std::vector<ReportEntry>& entries, const std::string& out_dir) {
    std::ostringstream b;
    const auto failed = std::count_if(entries.begin(), entries.end(), [](auto& e) { return !e.comparison.pass(); });
    b << "report: " << entries.size() << " scenes, " << entries.size() - size_t(failed) << " pass, " << failed
      << " fail\n";
    // One line per technique, in the order the scenes name them.
    const std::vector<std::string> kinds = techniques_in_order(entries);
    size_t width = 0;
    for (const auto& k : kinds) width = std::max(width, k.size());
    for (const std::string& kind : kinds) {
        long pass = 0, fail = 0;
        double lo = 0, hi = 0;
        bool timed = false;
        for (const auto& e : entries) {
            if (e.kind != kind) continue;
            (e.comparison.pass() ? pass : fail) += 1;
            if (e.cost && e.cost->gl.fps() > 0) {
                const double r = fps_ratio(*e.cost);
                lo = timed ? std::min(lo, r) : r, hi = timed ? std::max(hi, r) : r;
                timed = true;
            }
        }
        b << "  " << std::left << std::setw(int(width)) << kind << std::right << std::setw(5) << pass << " pass"
          << std::setw(4) << fail << " fail";
        if (timed) b << "   CPU / llvmpipe " << fixed(lo, 2) << (lo == hi ? "" : " to " + fixed(hi, 2));
        b << "\n";
    }
    const ReportEntry* worst = nullptr;
    for (const auto& e : entries)
        if (e.cost && e.cost->gl.fps() > 0 && (!worst || fps_ratio(*e.cost) < fps_ratio(*worst->cost))) worst = &e;
    if (worst)
        b << "slowest against llvmpipe: " << worst->scene << ", CPU / llvmpipe " << fixed(fps_ratio(*worst->cost), 2)
          << " (" << fixed(worst->cost->cpu.fps(), 1) << " against " << fixed(worst->cost->gl.fps(), 1) << " fps)\n";
    if (failed) {
        b << "failing:";
        int shown = 0;
        for (const auto& e : entries)
            if (!e.comparison.pass() && shown++ < 5) b << " " << e.scene;
        if (failed > 5) b << " and " << failed - 5 << " more";
        b << "\n";
    }
    b << "report: " << out_dir << "/index.html (tables: " << out_dir << "/summary.md)\n";
    return b.str();
}

}  // namespace st
