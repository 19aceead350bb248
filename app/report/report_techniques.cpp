// report_techniques.cpp: see report_techniques.h.
#include "app/report/report_techniques.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "app/markup_text.h"
#include "app/output_provenance.h"
#include "app/short_number.h"
#include "app/tool_data.h"
#include "image/file_provenance.h"
#include "image/image_io.h"

namespace st {

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The chart's own title: the first <text> element's content.
std::string svg_title(const std::string& svg) {
    const auto open = svg.find("<text");
    if (open == std::string::npos) return "";
    const auto start = svg.find('>', open);
    const auto end = svg.find("</text>", start);
    return start == std::string::npos || end == std::string::npos ? "" : svg.substr(start + 1, end - start - 1);
}

std::string number_cell(double v, int digits) { return "<td class=\"num\">" + short_number(v, digits) + "</td>"; }

// Our rates beside the paper's, in the paper's words and on its hardware.
void write_paper_table(std::ostringstream& h, const std::vector<const ReportEntry*>& rows) {
    std::vector<const ReportEntry*> with_paper;
    for (const ReportEntry* e : rows)
        if (e->paper) with_paper.push_back(e);
    // The papers' tables add techniques row by row, each slower than the one
    // before: their order is by falling frame rate.
    std::stable_sort(with_paper.begin(), with_paper.end(),
                     [](const ReportEntry* a, const ReportEntry* b) { return a->paper->fps > b->paper->fps; });
    if (with_paper.empty()) {
        h << "<p class=\"meta\">No published frame rate for these scenes (a scene's <code>paper</code> field gives "
             "one).</p>";
        return;
    }
    h << "<table class=\"paper\"><tr><th>paper's row</th><th>scene</th><th>paper, fps</th><th>paper's hardware</th>"
         "<th>llvmpipe, fps</th><th>shadertwin CPU, fps</th><th>CPU / llvmpipe</th></tr>";
    for (const ReportEntry* e : with_paper) {
        const PaperTiming& p = *e->paper;
        h << "<tr><td>" << markup_text(p.row) << "</td><td><a href=\"#s-" << markup_text(e->scene) << "\">"
          << markup_text(e->scene) << "</a></td>" << number_cell(p.fps, 3) << "<td>" << markup_text(p.hardware) << "</td>";
        if (e->cost && e->cost->gl.fps() > 0)
            h << number_cell(e->cost->gl.fps(), 3) << number_cell(e->cost->cpu.fps(), 3)
              << number_cell(e->cost->cpu.fps() / e->cost->gl.fps(), 3);
        else
            h << "<td>&ndash;</td><td>&ndash;</td><td>&ndash;</td>";
        h << "</tr>";
    }
    std::vector<std::string> sources;
    for (const ReportEntry* e : with_paper)
        if (std::find(sources.begin(), sources.end(), e->paper->source) == sources.end())
            sources.push_back(e->paper->source);
    h << "</table><p class=\"legend\">Paper: ";
    for (size_t i = 0; i < sources.size(); ++i) h << (i ? "; " : "") << markup_text(sources[i]);
    h << ". Its rates are a GPU's; ours are both CPU renderers on this machine, timed in the same run.</p>";
}

void cost_table(std::ostringstream& h, const std::vector<const ReportEntry*>& rows) {
    if (std::none_of(rows.begin(), rows.end(), [](const ReportEntry* e) { return e->cost.has_value(); })) {
        h << "<p class=\"meta\">Not timed (<code>--frames 0</code>).</p>";
        return;
    }
    h << "<table class=\"cost\"><tr><th>scene</th><th>size</th><th>CPU fps</th><th>llvmpipe fps</th>"
         "<th>CPU / llvmpipe</th><th>vertex ms</th><th>setup ms</th><th>raster ms</th><th>fragment ms</th>"
         "<th>output ms</th></tr>";
    for (const ReportEntry* e : rows) {
        if (!e->cost) continue;
        const BenchResult& r = *e->cost;
        h << "<tr><td><a href=\"#s-" << markup_text(e->scene) << "\">" << markup_text(e->scene) << "</a></td><td>"
          << r.width << "x" << r.height << "</td>" << number_cell(r.cpu.fps(), 4) << number_cell(r.gl.fps(), 4)
          << (r.gl.fps() > 0 ? number_cell(r.cpu.fps() / r.gl.fps(), 3) : "<td>&ndash;</td>")
          << number_cell(r.cpu_stages.vertex_ms, 3) << number_cell(r.cpu_stages.setup_ms, 3)
          << number_cell(r.cpu_stages.raster_ms, 3) << number_cell(r.cpu_stages.fragment_ms, 3)
          << number_cell(r.cpu_stages.output_ms, 3) << "</tr>";
    }
    h << "</table>";
}

}  // namespace

std::string paper_table(const std::vector<const ReportEntry*>& rows) {
    std::ostringstream h;
    write_paper_table(h, rows);
    return h.str();
}

std::vector<SweepChart> copy_sweep_charts(const std::vector<std::string>& techniques, const std::string& out_dir) {
    std::vector<SweepChart> charts;
    const auto dirs = sweep_chart_dirs();
    for (const std::string& technique : techniques) {
        const auto it = dirs.find(technique);
        std::error_code ec;
        if (it == dirs.end() || !fs::is_directory(it->second, ec)) continue;
        std::vector<fs::path> svgs;
        for (const auto& f : fs::directory_iterator(it->second, ec))
            if (f.path().extension() == ".svg") svgs.push_back(f.path());
        std::sort(svgs.begin(), svgs.end());
        for (const fs::path& svg : svgs) {
            const std::string text = read_text(svg);
            const std::string name = technique + "-" + svg.filename().string();
            std::error_code ec;
            fs::create_directories(fs::path(out_dir) / "charts", ec);
            if (ec) throw std::runtime_error("cannot create folder " + out_dir + "/charts: " + ec.message());
            // The sweep's own record stays the one read; this run adds that it copied it.
            write_copied_text_file(out_dir + "/charts/" + name, text);
            const std::string made = recorded_provenance(text);
            charts.push_back({technique, "charts/" + name,
                              svg_title(text) + ". From the sweep's last run kept with the tool (" +
                                  (made.empty() ? std::string("made before files recorded their provenance")
                                                : "made by " + made) +
                                  "); the red line joins the undominated settings, those no other setting beats on both speed and "
                                  "accuracy, and a black dot marks what quality: auto takes. Again: " +
                                  tool_name() + " sweep " + technique + " --out DIR"});
        }
    }
    return charts;
}

std::string technique_section(const std::vector<ReportEntry>& entries, const std::vector<SweepChart>& charts) {
    std::ostringstream h;
    h << "<h2 id=\"techniques\">Techniques</h2>\n";
    for (const std::string& technique : techniques_in_order(entries)) {
        std::vector<const ReportEntry*> rows;
        for (const ReportEntry& e : entries)
            if (e.kind == technique) rows.push_back(&e);
        // The paper's table follows the scenes' names, not the failures-first order.
        std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->scene < b->scene; });
        h << "<section class=\"technique\" id=\"t-" << markup_text(technique) << "\"><h3>" << markup_text(technique)
          << " (" << rows.size() << (rows.size() == 1 ? " scene" : " scenes") << ")</h3>";
        cost_table(h, rows);
        h << "<div class=\"strip\">";
        for (const SweepChart& c : charts)
            if (c.technique == technique)
                h << "<figure class=\"chart\"><a href=\"" << markup_text(c.src) << "\"><img src=\"" << markup_text(c.src)
                  << "\" width=\"480\" alt=\"speed against accuracy\"></a><figcaption>" << markup_text(c.caption)
                  << "</figcaption></figure>";
        h << "</div></section>\n";
    }
    return h.str();
}

}  // namespace st
