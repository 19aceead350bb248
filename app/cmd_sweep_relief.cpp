// cmd_sweep_relief.cpp: `sweep relief`, relief mapping's speed against its
// accuracy (issues 10, 28). For several view angles the relief-mapping scene
// is rendered on the CPU with each search setting (linear steps, binary
// steps, the secant step, and the count scaled by the view angle), and
// compared with the same program whose search is replaced by the exact
// crossing of the height map as the sampler reads it (app/quality/
// relief_exact.h, reference/relief_sampled_crossing.h), the reference
// `quality: auto` chooses against: the error of the hit in texels and in
// depth (the twin's output_hit mode writes hit_uv and t) and of the final
// image in 8-bit steps, versus the measured CPU frame time; and the image
// against the crossing of the bilinear surface in exact arithmetic
// (reference/relief_intersection.h), whose difference no setting removes.
// Settings that no other beats on both time and image error are marked,
// and the cheapest that keeps 99 % of the pixels within one 8-bit step is
// named.
// Writes a CSV of every setting, one SVG chart per angle, the exact and
// converged images with their heat map, and Markdown.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/tool_data.h"
#include "app/progress.h"
#include "app/memory_budget.h"
#include "app/backends.h"
#include "app/commands.h"
#include "app/quality/image_budget.h"
#include "app/quality/measured_costs.h"
#include "app/quality/relief_exact.h"
#include "app/quality/relief_quality.h"
#include "app/short_number.h"
#include "app/svg_chart.h"
#include "image/compare.h"
#include "image/image_io.h"
#include "image/unorm8.h"
#include "raster/cpu_renderer.h"
#include "scene/input_error.h"
#include "scene/scene.h"

namespace st {

namespace {

struct Setting {
    int linear = 16, min_linear = 0, binary = 6;
    bool secant = true;
    std::string label() const {
        std::ostringstream s;
        if (min_linear > 0) s << "mix(" << linear << "," << min_linear << ")";
        else s << linear;
        s << " / " << binary << (secant ? " / secant" : " / -");
        return s.str();
    }
};

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
    std::nth_element(v.begin(), v.begin() + long(k), v.end());
    return v[k];
}

// The 8-bit RGB difference of two images over the covered pixels (finite
// in the exact hit image): its RMS over channels, and per pixel the largest
// channel difference, whose 99.9th percentile, maximum and share above one
// step the tables show.
struct ImageError {
    double rms = 0, p999 = 0, max = 0, over_1lsb = 0;
};
struct Result {
    Setting setting;
    std::vector<double> ms;  // one per round
    double median_ms = 0;
    // Over the covered pixels: the hit's distance from the exact one in
    // level-0 texels, |t - t_exact| as a fraction of the layer's depth, and
    // the 8-bit RGB difference of the image.
    double texel_mean = 0, texel_p99 = 0, texel_max = 0;
    double depth_mean = 0, depth_max = 0;
    ImageError image;  // against the exact image of the sampled surface
    // Against the exact image of the bilinear surface: adds the floor that
    // the 8-bit filtered surface the search reads sets, which no setting
    // changes.
    ImageError bilinear;
    bool undominated = false;
};

// Far more steps than any setting: the most accurate search there is.
constexpr Setting kConverged{512, 0, 16, true};
// "Within one 8-bit step": at most this fraction of the covered pixels
// further off (image_budget.h). Not every pixel: where a ray grazes a
// stone's rim, a hit that no finite search finds decides it (see the heat
// maps).
constexpr double kWithinStep = kOverBudgetShare;


ImageError image_error(const Image& a, const Image& b, const Image& ref_hits) {
    std::vector<double> worst;
    double sq = 0;
    for (size_t p = 0; p < ref_hits.rgba.size() / 4; ++p) {
        if (!std::isfinite(ref_hits.rgba[4 * p])) continue;
        double w = 0;
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(to_unorm8(a.rgba[4 * p + c])) - double(to_unorm8(b.rgba[4 * p + c]));
            sq += d * d;
            w = std::max(w, std::abs(d));
        }
        worst.push_back(w);
    }
    if (worst.empty()) return {};
    const double n = double(worst.size());
    ImageError e;
    e.rms = std::sqrt(sq / (3 * n));
    e.p999 = quantile(worst, 0.999);
    e.max = *std::max_element(worst.begin(), worst.end());
    e.over_1lsb = double(std::count_if(worst.begin(), worst.end(), [](double w) { return w > 1; })) / n;
    return e;
}

// Every search setting quality: auto may choose for relief mapping: the
// sweep measures the frame times that order them (measured_costs.h).
std::vector<Setting> settings() {
    std::vector<Setting> out;
    for (const ReliefSetting& r : relief_search_settings("relief"))
        out.push_back(Setting{r.linear_steps, r.min_linear_steps, r.binary_steps, r.secant});
    return out;
}

// An int uniform set on every draw of the frame (replaced or added).
void set_int(Frame& f, const std::string& name, int value) {
    for (Pass& pass : f.passes)
        for (DrawCall& d : pass.draws) {
            auto it = std::find_if(d.uniforms.begin(), d.uniforms.end(), [&](const Uniform& u) { return u.name == name; });
            if (it == d.uniforms.end()) it = d.uniforms.insert(d.uniforms.end(), Uniform{name, UniformType::Int, {}});
            it->value[0] = float(value);
        }
}

Frame with_setting(Frame f, const Setting& s) {
    set_int(f, "linear_steps", s.linear);
    set_int(f, "min_linear_steps", s.min_linear);
    set_int(f, "binary_steps", s.binary);
    set_int(f, "secant", s.secant ? 1 : 0);
    return f;
}

// The hit frame: (hit_uv, t) as the colour, and a NaN clear colour so
// that uncovered pixels are known.
Frame hit_frame(Frame h) {
    set_int(h, "output_hit", 1);
    for (Pass& p : h.passes) p.clear_colour = glm::vec4(NAN);
    return h;
}


// The hit's error against the exact hit, over the covered pixels.
void measure_hits(Result& r, const Image& hits, const Image& ref_hits, int map_size) {
    std::vector<double> texel;
    double depth_sum = 0;
    for (size_t p = 0; p < ref_hits.rgba.size() / 4; ++p) {
        const float* e = &ref_hits.rgba[4 * p];
        if (!std::isfinite(e[0])) continue;  // uncovered
        const float* h = &hits.rgba[4 * p];
        const double du = (double(h[0]) - e[0]) * map_size, dv = (double(h[1]) - e[1]) * map_size;
        texel.push_back(std::sqrt(du * du + dv * dv));
        const double dt = std::abs(double(h[2]) - e[2]);
        depth_sum += dt;
        r.depth_max = std::max(r.depth_max, dt);
    }
    if (texel.empty()) return;
    const double n = double(texel.size());
    double texel_sum = 0;
    for (double t : texel) texel_sum += t;
    r.texel_mean = texel_sum / n;
    r.texel_p99 = quantile(texel, 0.99);
    r.texel_max = *std::max_element(texel.begin(), texel.end());
    r.depth_mean = depth_sum / n;
}


}  // namespace

int cmd_sweep_relief(const std::string& out_dir, int frames, const CommonOptions& common) {
    // Steep to grazing; past about 65 degrees at this field of view the
    // surface ends at a horizon (the clear pixels are not counted).
    const std::vector<double> angles = {30, 45, 60, 75, 85};
    const std::vector<Setting> all = settings();
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    const ReliefSweepTwins sweep_twins;
    CpuRenderer exact_renderer(common.threads, sweep_twins);

    std::ostringstream csv, md;
    csv << "angle_deg,linear_steps,min_linear_steps,binary_steps,secant,cpu_ms_median,texel_err_mean,texel_err_p99,"
           "texel_err_max,depth_err_mean,depth_err_max,image_rms_8bit,image_p999_8bit,image_max_8bit,"
           "pixels_over_1lsb,image_rms_vs_bilinear,pixels_over_1lsb_vs_bilinear,undominated\n";
    md << "# Relief mapping: speed against accuracy\n\n`shadertwin sweep relief --frames " << frames
       << "`: the relief-mapping scene on the CPU (" << common.threads
       << " threads) at each view angle, every setting against the exact crossing of the height map as the sampler "
          "reads it (8-bit filtered, on the levels the search reads: the answer every search converges to, and the "
          "reference of `quality: auto`). Time: median CPU frame over "
       << frames << " rounds, the settings interleaved. Texel error: distance of the hit from the exact one in "
          "level-0 texels; depth error: |t - t_exact| as a fraction of the layer's depth; image error: RMS of the "
          "8-bit RGB difference from the image shaded at the exact hit; *vs bilinear*: against the image shaded at "
          "the crossing of the bilinear surface in exact arithmetic, a difference the 8-bit filter makes and no "
          "setting removes. Settings are `linear / binary / secant`, "
          "`mix(max,min)` the count scaled by the view angle. **bold**: no other setting is both faster and more "
          "accurate (in image RMS).\n";
    bool ok = true;
    // Every angle's scene first, so that bad input stops the sweep before it
    // writes anything.
    std::vector<Scene> scenes;
    for (double angle : angles) {
        std::vector<std::string> overrides = common.overrides;
        overrides.push_back("view.angle_deg=" + short_number(angle));
        if (angle > 60) overrides.push_back("view.horizon_distance=6");
        scenes.push_back(load_scene("relief-mapping", overrides));
        if (scenes.back().frame.passes.front().draws.front().fragment != "relief_mapping")
            throw InputError("sweep relief: field 'technique' must stay \"relief\" (the sweep measures row 2's search)");
    }
    check_memory(scenes, MemoryUse::Compare, common.max_memory);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());
    Progress progress("sweep relief", angles.size());
    for (size_t a = 0; a < angles.size(); ++a) {
        const double angle = angles[a];
        const Scene& scene = scenes[a];
        // Texel errors are in the relief map's level-0 texels.
        int map_size = 0;
        for (const Texture& t : scene.frame.passes.front().draws.front().textures)
            if (t.sampler == "relief_map") map_size = t.width;
        const auto with_program = [&](const char* program) {
            Frame f = scene.frame;
            for (Pass& pass : f.passes)
                for (DrawCall& d : pass.draws) d.fragment = program;
            return f;
        };
        const Frame exact = with_program(ReliefSweepTwins::kSampledReliefMapping);
        const Image ref_image = exact_renderer.render(exact);
        const Image ref_hits = exact_renderer.render(hit_frame(exact));
        const Image bilinear_image = exact_renderer.render(with_program(ReliefSweepTwins::kExactReliefMapping));
        if (const std::string e = sweep_twins.take_error(); !e.empty())
            throw std::runtime_error("sweep relief: the exact image failed: " + e);
        const Image converged = backends.render(Backend::Cpu, with_setting(scene.frame, kConverged)).image;
        const std::string stem = out_dir + "/relief-sweep-" + short_number(angle) + "deg";
        write_png(stem + "-exact.png", ref_image);
        write_png(stem + "-bilinear.png", bilinear_image);
        write_png(stem + "-converged.png", converged);
        const std::vector<uint8_t> heat = heat_map(converged, ref_image);
        write_png_bytes(stem + "-converged-heat.png", ref_image.width, ref_image.height, 3, heat.data());
        const ImageError floor = image_error(ref_image, bilinear_image, ref_hits);

        std::vector<Result> results(all.size());
        for (size_t i = 0; i < all.size(); ++i) {
            results[i].setting = all[i];
            const Frame f = with_setting(scene.frame, all[i]);
            const Rendered first = backends.render(Backend::Cpu, f);
            results[i].ms.push_back(first.ms);
            measure_hits(results[i], backends.render(Backend::Cpu, hit_frame(f)).image, ref_hits, map_size);
            results[i].image = image_error(first.image, ref_image, ref_hits);
            results[i].bilinear = image_error(first.image, bilinear_image, ref_hits);
        }
        // The remaining rounds time every setting once each, so that the
        // machine's drift falls on all of them alike.
        for (int round = 1; round < frames; ++round)
            for (size_t i = 0; i < all.size(); ++i)
                results[i].ms.push_back(backends.render(Backend::Cpu, with_setting(scene.frame, all[i])).ms);
        // As the CSV will hold them, so that auto's mark below is what the
        // build reading the CSV chooses (measured_costs.h).
        for (Result& r : results) r.median_ms = measured_costs::as_written(quantile(r.ms, 0.5));

        // The setting quality: auto takes at this angle (budget 1), its
        // candidates ordered by the times just measured.
        const auto same = [](const Setting& t, const ReliefSetting& s) {
            return t.linear == s.linear_steps && t.min_linear == s.min_linear_steps && t.binary == s.binary_steps &&
                   t.secant == s.secant;
        };
        nlohmann::json auto_document = scene.document;
        auto_document["quality"] = "auto";
        const ReliefQualityChoice auto_choice = measure_relief_quality(
            sweep_twins, common.threads, scene.name, auto_document, 1, [&](const ReliefSetting& s, double) {
                for (const Result& r : results)
                    if (same(r.setting, s)) return r.median_ms;
                throw std::logic_error("sweep relief: auto's candidate " + s.label() + " was not timed");
            });
        for (Result& r : results) {
            r.undominated = std::none_of(results.begin(), results.end(), [&](const Result& o) {
                return o.median_ms <= r.median_ms && o.image.rms <= r.image.rms &&
                       (o.median_ms < r.median_ms || o.image.rms < r.image.rms);
            });
            ok &= std::isfinite(r.image.rms) && std::isfinite(r.texel_mean);
        }

        const Result* cheapest = nullptr;
        for (const Result& r : results)
            if (r.image.over_1lsb <= kWithinStep && (!cheapest || r.median_ms < cheapest->median_ms)) cheapest = &r;
        auto named = [](const Result* r) {
            return r ? "`" + r->setting.label() + "` (" + short_number(r->median_ms) + " ms)" : std::string("none");
        };
        md << "\n## View angle " << short_number(angle) << " degrees\n\n";
        const Result* auto_result = nullptr;
        for (const Result& r : results)
            if (same(r.setting, auto_choice.setting())) auto_result = &r;
        md << "`quality: auto` takes " << (auto_choice.chosen < 0 ? "(none within the budget: the most accurate) " : "")
           << named(auto_result)
           << " (the cheapest within one step for 99 % of the object against the exact crossing, measured at its "
              "costs' order, app/quality/relief_quality.h). ";
        md << "Cheapest setting of the sweep's whose image keeps 99 % of the pixels within one 8-bit step of the exact "
              "image: "
           << named(cheapest) << ". The exact image itself is " << short_number(floor.rms) << " steps RMS and "
           << short_number(100 * floor.over_1lsb)
           << " % of pixels more than a step from the bilinear surface's. Table 1's setting is `16 / 6 / secant`. "
              "Images: [exact](relief-sweep-" << short_number(angle)
           << "deg-exact.png), [bilinear surface](relief-sweep-" << short_number(angle) << "deg-bilinear.png), [`"
           << kConverged.label() << "`](relief-sweep-" << short_number(angle)
           << "deg-converged.png), [its difference from the exact image](relief-sweep-" << short_number(angle)
           << "deg-converged-heat.png).\n\n";
        md << "| setting | CPU ms | texel err mean / p99 / max | depth err mean / max | image RMS / p99.9 / max "
              "(8-bit) | pixels > 1 step | vs bilinear: RMS, pixels > 1 step |\n| --- | --- | --- | --- | --- | --- | --- |\n";
        ChartSeries fixed_secant{"linear+binary+secant", "#1f77b4", {}, {}, false, 2.5},
            fixed_plain{"linear+binary", "#ff7f0e", {}, {}, false, 2.5},
            scaled{"scaled by view angle", "#2ca02c", {}, {}, false, 3},
            front{"undominated", "#d62728", {}, {}, false, 0}, auto_mark{"quality: auto", "#000000", {}, {}, false, 5};
        if (auto_result) {
            auto_mark.x.push_back(auto_result->median_ms);
            auto_mark.y.push_back(std::max(auto_result->image.rms, 1e-3));
        }
        std::vector<const Result*> sorted;
        for (const Result& r : results) sorted.push_back(&r);
        std::sort(sorted.begin(), sorted.end(), [](const Result* a, const Result* b) { return a->median_ms < b->median_ms; });
        for (const Result* r : sorted) {
            const Setting& s = r->setting;
            ChartSeries& series = s.min_linear > 0 ? scaled : s.secant ? fixed_secant : fixed_plain;
            series.x.push_back(r->median_ms);
            series.y.push_back(std::max(r->image.rms, 1e-3));
            if (r->undominated) {
                front.x.push_back(r->median_ms);
                front.y.push_back(std::max(r->image.rms, 1e-3));
            }
            csv << angle << ',' << s.linear << ',' << s.min_linear << ',' << s.binary << ',' << s.secant << ','
                << r->median_ms << ',' << r->texel_mean << ',' << r->texel_p99 << ',' << r->texel_max << ','
                << r->depth_mean << ',' << r->depth_max << ',' << r->image.rms << ',' << r->image.p999 << ','
                << r->image.max << ',' << r->image.over_1lsb << ',' << r->bilinear.rms << ',' << r->bilinear.over_1lsb << ',' << r->undominated << '\n';
            const bool listed = r->undominated || r == cheapest || r == auto_result ||
                                (s.linear == 16 && s.min_linear == 0 && s.binary == 6 && s.secant);
            if (!listed) continue;
            const std::string name = r->undominated ? "**" + s.label() + "**" : s.label();
            md << "| " << name << " | " << short_number(r->median_ms) << " | " << short_number(r->texel_mean) << " / "
               << short_number(r->texel_p99) << " / " << short_number(r->texel_max) << " | " << short_number(r->depth_mean) << " / "
               << short_number(r->depth_max) << " | " << short_number(r->image.rms) << " / " << short_number(r->image.p999) << " / "
               << short_number(r->image.max) << " | " << short_number(100 * r->image.over_1lsb) << " % | " << short_number(r->bilinear.rms) << ", " << short_number(100 * r->bilinear.over_1lsb) << " % |\n";
        }
        Chart chart;
        chart.title = "Relief mapping at " + short_number(angle) + " degrees: image error against CPU time";
        chart.x_label = "CPU frame, ms (median)";
        chart.y_label = "image RMS error, 8-bit steps (floored at 1e-3)";
        chart.log_x = chart.log_y = true;
        chart.series = {fixed_plain, fixed_secant, scaled, front, auto_mark};
        const std::string svg = "relief-sweep-" + short_number(angle) + "deg.svg";
        write_text_file(out_dir + "/" + svg, chart.svg());
        md << "\n![" << short_number(angle) << " degrees](" << svg << ")\n";
        progress.step(short_number(angle) + " degrees done");
    }
    write_text_file(out_dir + "/relief-sweep.csv", csv.str());
    write_text_file(out_dir + "/relief-sweep.md", md.str());
    std::cout << md.str();
    return ok ? 0 : 1;
}

}  // namespace st
