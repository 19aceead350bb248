// report_page.cpp: see report_page.h. Plain HTML, one inline style sheet
// and one inline script (the wipe and flip); no network, no library.
#include "app/report/report_page.h"

#include "app/quality/quality_resolver.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "app/json_text.h"
#include "app/markup_text.h"
#include "app/short_number.h"

namespace st {

namespace {

std::string percent(double fraction) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(fraction == 1.0 || fraction == 0.0 ? 0 : 3) << 100.0 * fraction << " %";
    return s.str();
}

std::string anchor(const std::string& scene) { return "s-" + scene; }

// Images are shown at an integer scale that makes a small frame's pixels
// visible and keeps a large one within the page (image-rendering: pixelated).
int display_scale(int width) { return std::clamp(384 / std::max(width, 1), 1, 8); }

const char* kStyle = R"css(
body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}
h1{margin-bottom:.2em} .meta{color:#555;font-size:.9em}
table{border-collapse:collapse;margin:.6em 0} th,td{border:1px solid #ccc;padding:2px 8px;text-align:left}
th{background:#f2f2f2} td.num{text-align:right;font-variant-numeric:tabular-nums}
.pass{color:#060;font-weight:600} .fail{color:#b00;font-weight:600} tr.failed{background:#fff0f0}
details{border-top:1px solid #ddd;padding:.4em 0} summary{cursor:pointer;font-size:1.05em}
.strip{display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}
figure{margin:0} figcaption{font-size:.85em;color:#555}
img{image-rendering:pixelated;border:1px solid #888;display:block}
.viewer{position:relative;display:inline-block;border:1px solid #888}
.viewer img{border:0} .viewer .top{position:absolute;left:0;top:0}
.controls{font-size:.85em;margin:.3em 0} pre{background:#f6f6f6;padding:.4em;overflow-x:auto}
.legend{font-size:.85em;color:#444}
figure.chart{max-width:480px} figure.chart img{image-rendering:auto}
.gallery-row h2{font-size:1.15em;margin:.8em 0 .3em;display:inline-block} .gallery-row .meta{font-weight:normal}
.row{display:flex;flex-wrap:wrap;gap:16px;align-items:flex-start} .beside{flex:1 1 420px;min-width:320px}
.thumbs{display:flex;flex-wrap:wrap;gap:6px;flex:0 1 auto;max-width:880px}
a.thumb{display:block;width:100px;text-decoration:none;color:#333;font-size:.7em;overflow:hidden;white-space:nowrap;
 text-overflow:ellipsis;border:2px solid transparent;padding:1px} a.thumb img{border:1px solid #888;margin:0 auto}
a.thumb.failed{border-color:#c00;background:#fff0f0}
)css";

// The wipe shows the CPU image left of the slider and llvmpipe's right of
// it; flip swaps the whole image while the button is held or on each click.
const char* kScript = R"js(
// A link to a scene (the gallery's thumbnails, the summary's names) opens
// its folded detail.
function openFromHash() {
  var target = document.getElementById(decodeURIComponent(location.hash.slice(1)));
  if (target && target.tagName === 'DETAILS' && !target.open) { target.open = true; target.scrollIntoView(); }
}
window.addEventListener('hashchange', openFromHash);
openFromHash();
function setWipe(viewer, value) {
  viewer.querySelector('.top').style.clipPath = 'inset(0 ' + (100 - value) + '% 0 0)';
}
document.querySelectorAll('.viewer-box').forEach(function (box) {
  var viewer = box.querySelector('.viewer'), slider = box.querySelector('input[type=range]');
  var flip = box.querySelector('button'), label = box.querySelector('.showing');
  slider.addEventListener('input', function () { setWipe(viewer, slider.value); label.textContent = 'wipe: CPU left, llvmpipe right'; });
  flip.addEventListener('click', function () {
    var cpu = slider.value > 50;
    slider.value = cpu ? 0 : 100; setWipe(viewer, slider.value);
    label.textContent = cpu ? 'showing llvmpipe' : 'showing CPU';
  });
  setWipe(viewer, slider.value);
});
// Says on the page whether every image arrived (a folder copied without
// its images shows it at once); tests read the same from the DOM.
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var loaded = images.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
  var status = document.getElementById('images');
  status.dataset.loaded = loaded; status.dataset.total = images.length;
  status.textContent = loaded + ' of ' + images.length + ' images loaded.';
});
)js";

// One of the side-by-side images: at most kStripWidth wide so that four fit
// a row, pixelated when enlarged; a click opens it at full size.
constexpr int kStripWidth = 280;

void image_figure(std::ostringstream& h, const std::string& src, const std::string& caption, int width, int height,
                  int scale) {
    int w = width * scale, ht = height * scale;
    if (w > kStripWidth) {
        ht = std::max(1, int(std::lround(double(ht) * kStripWidth / w)));
        w = kStripWidth;
    }
    h << "<figure><a href=\"" << markup_text(src) << "\"><img src=\"" << markup_text(src) << "\" width=\"" << w << "\" height=\""
      << ht << "\" alt=\"" << markup_text(caption) << "\"></a><figcaption>" << markup_text(caption) << "</figcaption></figure>";
}

// CPU over llvmpipe, wiped or flipped.
void viewer(std::ostringstream& h, const std::string& cpu, const std::string& gl, int width, int height, int scale) {
    const std::string size = "width=\"" + std::to_string(width * scale) + "\" height=\"" + std::to_string(height * scale) + "\"";
    h << "<div class=\"viewer-box\"><div class=\"viewer\"><img src=\"" << markup_text(gl) << "\" " << size
      << " alt=\"llvmpipe\"><img class=\"top\" src=\"" << markup_text(cpu) << "\" " << size << " alt=\"CPU\"></div>"
      << "<div class=\"controls\"><input type=\"range\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"wipe\"> "
      << "<button type=\"button\">flip</button> <span class=\"showing\">wipe: CPU left, llvmpipe right</span></div></div>";
}

void metrics_table(std::ostringstream& h, const nlohmann::json& j) {
    h << "<table class=\"metrics\"><tr><th>metric</th><th>value</th></tr>";
    for (const auto& [key, value] : j.items()) {
        if (key == "failures" || key == "scene" || key == "outputs" || key == "pass") continue;
        h << "<tr><td>" << markup_text(key) << "</td><td class=\"num\">"
          << markup_text(value.is_string() ? value.get<std::string>() : json_text(value)) << "</td></tr>";
    }
    h << "</table>";
}

std::string fps_ratio(const ReportEntry& e) {
    if (!e.cost || e.cost->gl.fps() <= 0) return "&ndash;";
    return short_number(e.cost->cpu.fps() / e.cost->gl.fps(), 3);
}

}  // namespace

std::vector<std::string> techniques_in_order(const std::vector<ReportEntry>& entries) {
    std::vector<std::string> out;
    for (const ReportEntry& e : entries)
        if (std::find(out.begin(), out.end(), e.kind) == out.end()) out.push_back(e.kind);
    return out;
}

std::string report_page(const ReportHeader& header, const std::vector<ReportEntry>& entries,
                        const std::string& techniques, const std::string& gallery) {
    const long failed = std::count_if(entries.begin(), entries.end(), [](auto& e) { return !e.comparison.pass(); });
    std::ostringstream h;
    h << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>shadertwin report</title><style>"
      << kStyle << "</style></head><body>\n<h1>shadertwin report</h1><p class=\"meta\">" << markup_text(header.provenance)
      << "</p>\n<p id=\"counts\" data-scenes=\"" << entries.size() << "\" data-failed=\"" << failed << "\">"
      << entries.size() - size_t(failed) << " of " << entries.size() << " scenes pass"
      << (failed ? ", " + std::to_string(failed) + " fail" : std::string()) << ".</p>\n" << gallery;

    // The summary: one row per scene, failures first.
    h << "<h2 id=\"results\">Every scene</h2><table id=\"summary\"><tr><th>scene</th><th>technique</th><th>result</th><th>identical (float)</th>"
         "<th>identical (8-bit)</th><th>largest difference (8-bit LSB)</th><th>largest relative difference (float)</th>"
         "<th>fps, CPU / llvmpipe</th></tr>\n";
    for (const ReportEntry& e : entries) {
        const SceneComparison& c = e.comparison;
        h << "<tr class=\"" << (c.pass() ? "passed" : "failed") << "\"><td><a href=\"#" << markup_text(anchor(e.scene)) << "\">"
          << markup_text(e.scene) << "</a></td><td>" << markup_text(e.kind) << "</td><td class=\"" << (c.pass() ? "pass\">pass" : "fail\">FAIL")
          << "</td><td class=\"num\">" << percent(c.metrics.identical_fraction_float) << "</td><td class=\"num\">"
          << percent(c.metrics.identical_fraction_8bit) << "</td><td class=\"num\">" << c.metrics.max_diff_8bit
          << "</td><td class=\"num\">" << short_number(c.metrics.max_rel_diff_float, 3) << "</td><td class=\"num\">"
          << fps_ratio(e) << "</td></tr>\n";
    }
    h << "</table>\n<p class=\"legend\">Heat maps: black = bit-identical floats, dark blue = floats differ but 8-bit "
         "equal, green = 1 LSB, yellow = 2-3 LSB, red = 4+ LSB, white = non-finite. Coverage maps: where the number of "
         "fragments per pixel differs. Condition maps: white where the scene's failure conditions allow a difference."
         "</p>\n"
      << techniques << "<h2 id=\"scenes\">Scenes</h2>\n";

    // Each scene's detail, folded; a failing one open.
    for (const ReportEntry& e : entries) {
        const SceneComparison& c = e.comparison;
        const int scale = display_scale(c.metrics.width);
        const int w = c.metrics.width, ht = c.metrics.height;
        h << "<details id=\"" << markup_text(anchor(e.scene)) << "\"" << (c.pass() ? "" : " open") << "><summary><b>"
          << markup_text(e.scene) << "</b> (" << markup_text(e.kind) << ") <span class=\"" << (c.pass() ? "pass\">pass" : "fail\">FAIL")
          << "</span></summary>\n";
        for (const auto& f : c.failures) h << "<p class=\"fail\">" << markup_text(f) << "</p>";
        if (!e.quality.is_null()) h << "<p class=\"quality\">" << markup_text(quality_summary(e.quality)) << "</p>";
        viewer(h, c.cpu_png, c.gl_png, w, ht, scale);
        h << "<div class=\"strip\">";
        image_figure(h, c.cpu_png, "CPU (twins)", w, ht, scale);
        image_figure(h, c.gl_png, c.gl_png == c.cpu_png ? "llvmpipe (GLSL): the CPU's image to the bit" : "llvmpipe (GLSL)",
                     w, ht, scale);
        image_figure(h, c.diff_png, "heat map", w, ht, scale);
        image_figure(h, c.coverage_diff_png, "coverage map", w, ht, scale);
        if (!c.condition_png.empty()) image_figure(h, c.condition_png, "condition map", w, ht, scale);
        h << "</div>";
        metrics_table(h, to_json(c));
        for (const OutputComparison& o : c.outputs) {
            const int os = display_scale(o.metrics.width);
            h << "<h3>" << markup_text(o.name) << " <span class=\"" << (o.failures.empty() ? "pass\">pass" : "fail\">FAIL")
              << "</span></h3>";
            for (const auto& f : o.failures) h << "<p class=\"fail\">" << markup_text(f) << "</p>";
            viewer(h, o.cpu_png, o.gl_png, o.metrics.width, o.metrics.height, os);
            h << "<div class=\"strip\">";
            image_figure(h, o.cpu_png, "CPU", o.metrics.width, o.metrics.height, os);
            image_figure(h, o.gl_png, o.gl_png == o.cpu_png ? "llvmpipe: the CPU's image to the bit" : "llvmpipe",
                         o.metrics.width, o.metrics.height, os);
            image_figure(h, o.diff_png, "heat map", o.metrics.width, o.metrics.height, os);
            h << "</div><table class=\"metrics\"><tr><th>identical (float)</th><th>largest difference (8-bit LSB)</th>"
                 "<th>largest relative difference (float)</th></tr><tr><td class=\"num\">"
              << percent(o.metrics.identical_fraction_float) << "</td><td class=\"num\">" << o.metrics.max_diff_8bit
              << "</td><td class=\"num\">" << short_number(o.metrics.max_rel_diff_float, 3) << "</td></tr></table>";
        }
        if (e.cost) {
            const BenchResult& r = *e.cost;
            h << "<table class=\"cost\"><tr><th>backend</th><th>fps</th><th>ms median</th><th>ms min</th><th>ms max</th>"
                 "</tr><tr><td>CPU, "
              << r.cpu_threads << " threads</td><td class=\"num\">" << short_number(r.cpu.fps(), 4)
              << "</td><td class=\"num\">" << short_number(r.cpu.ms_median, 4) << "</td><td class=\"num\">"
              << short_number(r.cpu.ms_min, 4) << "</td><td class=\"num\">" << short_number(r.cpu.ms_max, 4)
              << "</td></tr><tr><td>llvmpipe, LP_NUM_THREADS " << markup_text(r.gl_threads) << "</td><td class=\"num\">"
              << short_number(r.gl.fps(), 4) << "</td><td class=\"num\">" << short_number(r.gl.ms_median, 4)
              << "</td><td class=\"num\">" << short_number(r.gl.ms_min, 4) << "</td><td class=\"num\">"
              << short_number(r.gl.ms_max, 4) << "</td></tr></table>";
        }
        h << "<pre><code>" << markup_text(header.tool) << " compare " << markup_text(e.scene) << " --out " << markup_text(header.out_dir)
          << "     # reproduce\n"
          << markup_text(header.tool) << " golden update " << markup_text(e.scene) << "     # accept the CPU image as the golden one"
          << "</code></pre></details>\n";
    }
    h << "<p id=\"images\" class=\"meta\"></p><script>" << kScript << "</script>\n</body></html>\n";
    return h.str();
}

}  // namespace st
