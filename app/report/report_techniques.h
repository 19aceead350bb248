// report_techniques.h: the report's per-technique part: its cost table
// (both backends, CPU stages) and its speed-against-accuracy charts with the
// undominated settings marked; and each technique's fps beside the paper's,
// which the gallery shows (report_gallery.h).
#pragma once

#include <string>
#include <vector>

#include "app/report/report_page.h"

namespace st {

// A chart a sweep drew (SVG), copied into the report folder.
struct SweepChart {
    std::string technique;  // the scene kind it belongs to: "relief"
    std::string src;        // relative to the report's index.html
    std::string caption;    // what it shows, when it was made and how to make it again
};

// Copies every *.svg of the chart folders of `techniques` into
// `out_dir`/charts/ and describes each. Folders that do not exist are skipped.
std::vector<SweepChart> copy_sweep_charts(const std::vector<std::string>& techniques, const std::string& out_dir);

// Our frame rates beside the paper's for the scenes that give one (their
// `paper` field), in the paper's order; or a line saying there is none.
std::string paper_table(const std::vector<const ReportEntry*>& rows);

// The HTML section, one subsection per technique in the order the entries
// first name it.
std::string technique_section(const std::vector<ReportEntry>& entries, const std::vector<SweepChart>& charts);

}  // namespace st
