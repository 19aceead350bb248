// report_summary.h: what `report` prints and keeps as text: the Markdown
// tables (every scene's metrics, then the cost table), written to
// DIR/summary.md and, as before, to stdout; and the brief form, a few lines
// that say what the run found (scenes passed and failed per technique, the
// worst speed ratio, where the report is), which `report --brief` prints
// instead (./run.sh).
#pragma once

#include <string>
#include <vector>

#include "app/report/report_page.h"

namespace st {

// `entries` in the report's order (failures first).
std::string report_markdown(const std::vector<ReportEntry>& entries, const std::string& renderer, int frames);
std::string report_brief(const std::vector<ReportEntry>& entries, const std::string& out_dir);

}  // namespace st
