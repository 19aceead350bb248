// thin_slab_speed.cpp: see thin_slab_speed.h.
#include "app/quality/thin_slab_speed.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "app/median.h"
#include "app/quality/image_budget.h"
#include "app/quality/measured_costs.h"
#include "app/quality/thin_slab_exact.h"
#include "app/quality/thin_slab_quality.h"
#include "app/short_number.h"
#include "app/svg_chart.h"
#include "image/image_io.h"
#include "image/unorm8.h"
#include "raster/cpu_renderer.h"
#include "raster/stage_times.h"
#include "scene/scene.h"

namespace st {

namespace {

struct LightPath {
    const char* name;
    const char* scene;
    std::vector<std::string> overrides;
};

const LightPath kPaths[] = {
    {"backlit", "thin-slab-fragment-backlit", {}},
    {"frontlit", "thin-slab-fragment-frontlit", {}},
    {"grazing", "thin-slab-fragment-frontlit", {"light.position=[1.5,0,0]"}},  // near the flag's plane
};
constexpr std::pair<int, int> kMeshes[] = {{4, 3}, {11, 8}, {22, 16}, {44, 32}, {88, 64}, {176, 128}};
constexpr const char* kAllVariants[] = {"baseline", "vertex", "host", "fragment"};
const char* kColours[] = {"#7f7f7f", "#1f77b4", "#ff7f0e", "#2ca02c"};

struct Row {
    std::string path, variant;
    int columns = 0, rows = 0;
    double median_ms = 0, rms = 0, over_1 = 0;
    bool undominated = false, auto_choice = false;
};

// RMS of the 8-bit RGB difference over the flag's pixels (either image
// not black), and the share of those more than one step off.
std::pair<double, double> image_rms(const Image& a, const Image& reference) {
    double sq = 0, n = 0;
    for (size_t p = 0; p + 3 < reference.rgba.size(); p += 4) {
        bool object = false;
        double worst = 0, sum = 0;
        for (size_t c = 0; c < 3; ++c) {
            const uint8_t x = to_unorm8(a.rgba[p + c]), r = to_unorm8(reference.rgba[p + c]);
            object |= x != 0 || r != 0;
            const double d = double(x) - double(r);
            sum += d * d;
            worst = std::max(worst, std::abs(d));
        }
        if (object) sq += sum, n += 3;
    }
    return {n > 0 ? std::sqrt(sq / n) : 0.0, object_error(a, reference, 1.0).over_budget};
}

}  // namespace

std::string thin_slab_speed_accuracy(const std::string& out_dir, int frames, const CommonOptions& common) {
    static const ThinSlabExactTwins twins;
    std::ostringstream md, csv;
    md << "\n## Speed against accuracy\n\nEach variant at six flag meshes on three light paths (the built-in scenes' "
          "flag and camera, 512x512; `grazing`: the frontlit scene with the light at (1.5, 0, 0), near the flag's "
          "plane), on the CPU with "
       << common.threads << " threads: median frame of " << frames
       << " interleaved rounds, against the fragment variant in exact arithmetic (app/quality/thin_slab_exact.h): RMS "
          "of the 8-bit RGB difference over the flag's pixels and the share more than one step off. **bold**: no "
          "other variant on the same light path is both faster and more accurate; *auto*: what `quality: auto` "
          "takes at that mesh (budget 1).\n\n"
          "| light | mesh (quads) | variant | CPU ms | RMS (8-bit) | pixels > 1 step | |\n| --- | --- | --- | --- | --- | --- | --- |\n";
    csv << "light,columns,rows,variant,cpu_ms_median,rms_8bit,pixels_over_1lsb,undominated,auto\n";
    // Every path's times first, so that auto's choice at each mesh is made
    // in the order the build will read from this CSV (measured_costs.h:
    // the nearest mesh, averaged over the paths).
    std::vector<std::vector<Row>> all_rows;
    std::vector<measured_costs::ThinSlabRow> timed;
    std::vector<std::pair<std::string, nlohmann::json>> auto_documents;  // per (path, mesh), in order
    for (const LightPath& path : kPaths) {
        std::vector<Row>& rows = all_rows.emplace_back();
        for (auto [columns, quad_rows] : kMeshes) {
            std::vector<std::string> overrides = common.overrides;
            for (const std::string& o : path.overrides) overrides.push_back(o);
            overrides.push_back("flag.columns=" + std::to_string(columns));
            overrides.push_back("flag.rows=" + std::to_string(quad_rows));
            const Scene base = load_scene(path.scene, overrides);
            CpuRenderer exact_renderer(common.threads, twins);
            Frame exact = base.frame;
            for (Pass& pass : exact.passes)
                for (DrawCall& d : pass.draws)
                    if (d.fragment == "thin_slab") d.fragment = ThinSlabExactTwins::kExactThinSlab;
            const Image reference = exact_renderer.render(exact);
            nlohmann::json document = base.document;
            document["quality"] = "auto";
            auto_documents.emplace_back(base.name, document);
            // Every variant prepared once, then timed in interleaved rounds.
            std::vector<std::unique_ptr<CpuRenderer>> renderers;
            std::vector<std::vector<double>> ms(std::size(kAllVariants));
            for (const char* variant : kAllVariants) {
                const Scene s = load_scene_document(base.name, with_thin_slab_variant(base.document, variant), "");
                auto& r = renderers.emplace_back(std::make_unique<CpuRenderer>(common.threads, twins));
                Row row;
                row.path = path.name, row.variant = variant, row.columns = columns, row.rows = quad_rows;
                std::tie(row.rms, row.over_1) = image_rms(r->render(s.frame), reference);
                rows.push_back(row);
            }
            for (int round = 0; round < frames; ++round)
                for (size_t v = 0; v < renderers.size(); ++v) {
                    const auto t0 = Clock::now();
                    renderers[v]->execute();
                    ms[v].push_back(ms_between(t0, Clock::now()));
                }
            for (size_t v = 0; v < renderers.size(); ++v) {
                Row& row = rows[rows.size() - renderers.size() + v];
                row.median_ms = measured_costs::as_written(median(ms[v]));  // as the CSV holds it
                timed.push_back({row.path, row.columns, row.rows, row.variant, row.median_ms});
            }
        }
    }
    // The variant quality: auto takes at each mesh, ordered by these times.
    size_t next_auto = 0;
    for (std::vector<Row>& rows : all_rows)
        for (size_t m = 0; m < std::size(kMeshes); ++m) {
            const auto& [name, document] = auto_documents[next_auto++];
            const std::string chosen =
                measure_thin_slab_quality(twins, common.threads, name, document, 1, [&](const std::string& v, int quads) {
                    return measured_costs::thin_slab_variant_ms(timed, v, double(quads));
                }).variant();
            for (size_t v = 0; v < std::size(kAllVariants); ++v) {
                Row& row = rows[m * std::size(kAllVariants) + v];
                row.auto_choice = chosen == row.variant;
            }
        }
    for (size_t p = 0; p < std::size(kPaths); ++p) {
        const LightPath& path = kPaths[p];
        std::vector<Row>& rows = all_rows[p];
        for (Row& r : rows)
            r.undominated = std::none_of(rows.begin(), rows.end(), [&](const Row& o) {
                return o.median_ms <= r.median_ms && o.rms <= r.rms && (o.median_ms < r.median_ms || o.rms < r.rms);
            });
        Chart chart;
        chart.title = std::string("Thin slab, ") + path.name + ": image error against CPU time";
        chart.x_label = "CPU frame, ms (median)";
        chart.y_label = "RMS against exact arithmetic, 8-bit steps (floored at 1e-3)";
        chart.log_x = chart.log_y = true;
        ChartSeries front{"undominated", "#d62728", {}, {}, false, 0}, chosen{"quality: auto", "#000000", {}, {}, false, 5};
        for (size_t v = 0; v < std::size(kAllVariants); ++v) {
            ChartSeries s{kAllVariants[v], kColours[v], {}, {}, false, 3};
            for (const Row& r : rows)
                if (r.variant == kAllVariants[v]) s.x.push_back(r.median_ms), s.y.push_back(std::max(r.rms, 1e-3));
            chart.series.push_back(s);
        }
        std::vector<const Row*> sorted;
        for (const Row& r : rows) sorted.push_back(&r);
        std::sort(sorted.begin(), sorted.end(), [](const Row* a, const Row* b) { return a->median_ms < b->median_ms; });
        for (const Row* r : sorted) {
            if (r->undominated) front.x.push_back(r->median_ms), front.y.push_back(std::max(r->rms, 1e-3));
            if (r->auto_choice) chosen.x.push_back(r->median_ms), chosen.y.push_back(std::max(r->rms, 1e-3));
        }
        chart.series.push_back(front);
        chart.series.push_back(chosen);
        const std::string svg = std::string("thin-slab-speed-") + path.name + ".svg";
        write_text_file(out_dir + "/" + svg, chart.svg());
        for (const Row& r : rows) {
            csv << r.path << ',' << r.columns << ',' << r.rows << ',' << r.variant << ',' << r.median_ms << ',' << r.rms
                << ',' << r.over_1 << ',' << r.undominated << ',' << r.auto_choice << '\n';
            const std::string variant = r.undominated ? "**" + r.variant + "**" : r.variant;
            md << "| " << r.path << " | " << r.columns << " x " << r.rows << " | " << variant << " | "
               << short_number(r.median_ms) << " | " << short_number(r.rms) << " | " << short_number(100 * r.over_1)
               << " % | " << (r.auto_choice ? "*auto*" : "") << " |\n";
        }
        md << "\n![" << path.name << "](" << svg << ")\n\n";
        if (&path != &kPaths[std::size(kPaths) - 1])
            md << "| light | mesh (quads) | variant | CPU ms | RMS (8-bit) | pixels > 1 step | |\n| --- | --- | --- | --- | "
                  "--- | --- | --- |\n";
    }
    write_text_file(out_dir + "/thin-slab-speed.csv", csv.str());
    return md.str();
}

}  // namespace st
