// report_gallery.cpp: see report_gallery.h.
#include "app/report/report_gallery.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/markup_text.h"
#include "app/report/report_techniques.h"

namespace st {

namespace {

// Thumbnails are this wide (taller ones this tall), enlarged pixelated
// when the scene is smaller.
constexpr int kThumb = 96;

void thumbnail(std::ostringstream& h, const ReportEntry& e) {
    const SceneComparison& c = e.comparison;
    const int w = std::max(c.metrics.width, 1), ht = std::max(c.metrics.height, 1);
    const double scale = double(kThumb) / double(std::max(w, ht));
    const int tw = std::max(1, int(std::lround(w * scale))), th = std::max(1, int(std::lround(ht * scale)));
    h << "<a class=\"thumb" << (c.pass() ? "" : " failed") << "\" href=\"#s-" << markup_text(e.scene) << "\" title=\""
      << markup_text(e.scene) << (c.pass() ? "" : " (FAIL)") << "\"><img src=\"" << markup_text(c.cpu_png)
      << "\" width=\"" << tw << "\" height=\"" << th << "\" alt=\"" << markup_text(e.scene) << "\" loading=\"lazy\"><span>"
      << markup_text(e.scene) << "</span></a>";
}

}  // namespace

std::string report_gallery(const std::vector<ReportEntry>& entries) {
    std::vector<std::string> kinds = techniques_in_order(entries);
    // Techniques first, the conformance scenes last.
    std::stable_partition(kinds.begin(), kinds.end(), [](const std::string& k) { return k != "conformance"; });
    std::ostringstream h;
    h << "<section id=\"gallery\">\n";
    for (const std::string& kind : kinds) {
        std::vector<const ReportEntry*> rows;
        for (const ReportEntry& e : entries)
            if (e.kind == kind) rows.push_back(&e);
        std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->scene < b->scene; });
        const long failed = std::count_if(rows.begin(), rows.end(), [](auto* e) { return !e->comparison.pass(); });
        std::ostringstream title;
        title << markup_text(kind) << " <span class=\"meta\">" << rows.size() << (rows.size() == 1 ? " scene" : " scenes")
              << ", " << (failed ? "<span class=\"fail\">" + std::to_string(failed) + " fail</span>" : std::string("all pass"))
              << "</span>";
        std::ostringstream thumbs;
        thumbs << "<div class=\"thumbs\">";
        for (const ReportEntry* e : rows) thumbnail(thumbs, *e);
        thumbs << "</div>";
        if (kind == "conformance") {
            h << "<details class=\"gallery-row\" id=\"g-" << markup_text(kind) << "\"" << (failed ? " open" : "")
              << "><summary><h2>" << title.str() << "</h2></summary>" << thumbs.str() << "</details>\n";
        } else {
            h << "<section class=\"gallery-row\" id=\"g-" << markup_text(kind) << "\"><h2>" << title.str() << "</h2>"
              << "<div class=\"row\">" << thumbs.str() << "<div class=\"beside\">" << paper_table(rows)
              << "</div></div></section>\n";
        }
    }
    h << "</section>\n";
    return h.str();
}

}  // namespace st
