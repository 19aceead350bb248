// cmd_sweep_profile.cpp: `sweep profile`, the gather's speed against its
// accuracy (issue 11). The flat-slab scene (profile-slab-edge, or the scene
// given by --scene) is rendered on the CPU with each gather setting (sample
// pattern, sample count, texture-space resolution) and compared with its
// exact image (app/profile_exact.h: the convolution of the sharp-edged light
// with the profile, in double precision): RMS and largest 8-bit error and
// the share of pixels more than one step off, over the pixels at least the
// profile's reach inside the slab (and, apart, over the band nearer its
// edges, where the finite slab is not the convolution's infinite plane),
// versus the measured CPU frame time. Settings that no other beats on both
// are marked; the cheapest that keeps 99 % of the interior pixels within one
// 8-bit step is named (the shadow edge, sharper than a texel of the
// texture-space target, keeps a few pixels beyond it at any sample count).
// The physics apart: each setting's interior also against the exact image
// of the material's Monte Carlo profile, where the model's own error joins
// the gather's. Writes a CSV, an SVG chart, the exact image and heat maps,
// and Markdown.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/tool_data.h"
#include "app/median.h"
#include "app/memory_budget.h"
#include "app/backends.h"
#include "app/commands.h"
#include "app/profile_exact.h"
#include "app/quality/profile_quality.h"
#include "app/progress.h"
#include "app/short_number.h"
#include "app/svg_chart.h"
#include "image/compare.h"
#include "image/image_io.h"
#include "image/unorm8.h"
#include "scene/input_error.h"
#include "scene/scene.h"

namespace st {

namespace {

struct ProfileSetting {
    std::string pattern;
    int samples = 64, texture_size = 256;
    std::string label() const {
        return pattern + " " + std::to_string(samples) + " @" + std::to_string(texture_size);
    }
};

// The budget: at most this share of the interior pixels more than one 8-bit
// step from the exact image.
constexpr double kInteriorWithinStep = 0.01;

struct RegionError {
    double rms = 0, max = 0, over_1lsb = 0;  // 8-bit steps
    double rel_rms = 0;                      // float: RMS difference over the mean exact value
};

struct ProfileResult {
    ProfileSetting setting;
    std::vector<double> ms;
    double median_ms = 0;
    RegionError interior, edge_band;
    RegionError physics;  // the interior against the exact image of the Monte Carlo profile
    bool undominated = false;
};

RegionError region_error(const Image& img, const ProfileExact& exact, uint8_t region) {
    double sq = 0, fsq = 0, fsum = 0, worst = 0;
    size_t n = 0, over = 0;
    for (size_t p = 0; p < exact.region.size(); ++p) {
        if (exact.region[p] != region) continue;
        double w = 0;
        for (size_t c = 0; c < 3; ++c) {
            const float a = img.rgba[4 * p + c], e = exact.image.rgba[4 * p + c];
            const double d = double(to_unorm8(a)) - double(to_unorm8(e));
            sq += d * d;
            w = std::max(w, std::abs(d));
            fsq += (double(a) - e) * (double(a) - e);
            fsum += e;
        }
        worst = std::max(worst, w);
        over += w > 1;
        ++n;
    }
    if (!n) return {};
    RegionError e;
    e.rms = std::sqrt(sq / (3.0 * double(n)));
    e.max = worst;
    e.over_1lsb = double(over) / double(n);
    e.rel_rms = fsum > 0 ? std::sqrt(fsq / (3.0 * double(n))) / (fsum / (3.0 * double(n))) : 0;
    return e;
}

std::vector<ProfileSetting> profile_settings() {
    std::vector<ProfileSetting> out;
    for (const char* pattern : {"importance", "disk"})
        for (int texture_size : {128, 256, 512})
            for (int samples : {4, 8, 16, 32, 64, 128, 256, 512, 1024}) out.push_back(ProfileSetting{pattern, samples, texture_size});
    return out;
}

std::vector<std::string> overrides_of(const std::vector<std::string>& common, const ProfileSetting& s) {
    std::vector<std::string> o = common;
    o.push_back("gather.pattern=" + s.pattern);
    o.push_back("gather.samples=" + std::to_string(s.samples));
    o.push_back("geometry.texture_size=" + std::to_string(s.texture_size));
    return o;
}


}  // namespace

int cmd_sweep_profile(const std::string& scene_name, const std::string& out_dir, int frames,
                      const CommonOptions& common) {
    const std::vector<ProfileSetting> all = profile_settings();
    // Every setting's scene and the exact image first: bad input stops the
    // sweep before it writes anything.
    std::vector<Scene> scenes;
    for (const ProfileSetting& s : all) scenes.push_back(load_scene(scene_name, overrides_of(common.overrides, s)));
    check_memory(scenes, MemoryUse::Compare, common.max_memory);
    const auto exact_start = std::chrono::steady_clock::now();
    const ProfileExact exact = exact_profile_image(scenes.front());
    const double exact_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - exact_start).count();
    // The physics: the same convolution with the material's Monte Carlo
    // profile (its bins reaching as quality: auto's reference does), over
    // the same interior, so that the error of the model joins the gather's.
    nlohmann::json mc_document = with_choice(scenes.front().document, "mc", 1);
    mc_document["material"]["mc_r_max_mm"] = reference_reach_mm(mc_document["material"]);
    ProfileExact exact_mc = exact_profile_image(load_scene_document(scene_name, mc_document, ""));
    exact_mc.region = exact.region;
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());

    Backends backends(common.threads, common.gl_platform, glsl_roots());
    std::vector<ProfileResult> results(all.size());
    std::vector<Image> images(all.size());
    Progress progress("sweep profile", all.size() * size_t(std::max(frames, 1)));
    const auto label = [&](size_t i, int round) { return all[i].label() + ", round " + std::to_string(round + 1); };
    for (size_t i = 0; i < all.size(); ++i) {
        progress.step(label(i, 0));
        results[i].setting = all[i];
        const Rendered first = backends.render(Backend::Cpu, scenes[i].frame);
        results[i].ms.push_back(first.ms);
        results[i].interior = region_error(first.image, exact, 1);
        results[i].edge_band = region_error(first.image, exact, 2);
        results[i].physics = region_error(first.image, exact_mc, 1);
        images[i] = first.image;
    }
    // The other rounds time every setting once each, so that the machine's
    // drift falls on all of them alike.
    for (int round = 1; round < frames; ++round)
        for (size_t i = 0; i < all.size(); ++i) {
            progress.step(label(i, round));
            results[i].ms.push_back(backends.render(Backend::Cpu, scenes[i].frame).ms);
        }
    bool ok = true;
    for (ProfileResult& r : results) r.median_ms = median(r.ms);
    for (ProfileResult& r : results) {
        r.undominated = std::none_of(results.begin(), results.end(), [&](const ProfileResult& o) {
            return o.median_ms <= r.median_ms && o.interior.rms <= r.interior.rms &&
                   (o.median_ms < r.median_ms || o.interior.rms < r.interior.rms);
        });
        ok &= std::isfinite(r.interior.rms) && std::isfinite(r.edge_band.rms);
    }
    const ProfileResult* cheapest = nullptr;
    for (const ProfileResult& r : results)
        if (r.interior.over_1lsb <= kInteriorWithinStep && (!cheapest || r.median_ms < cheapest->median_ms)) cheapest = &r;

    write_png(out_dir + "/profile-sweep-exact.png", exact.image);
    const ProfileResult* best = &results.front();
    for (const ProfileResult& r : results)
        if (r.interior.rms < best->interior.rms) best = &r;
    const Image& best_image = images[size_t(best - results.data())];
    write_png(out_dir + "/profile-sweep-best.png", best_image);
    const std::vector<uint8_t> heat = heat_map(best_image, exact.image);
    write_png_bytes(out_dir + "/profile-sweep-best-heat.png", exact.image.width, exact.image.height, 3, heat.data());

    std::ostringstream csv, md;
    csv << "pattern,samples,texture_size,cpu_ms_median,interior_rms_8bit,interior_max_8bit,interior_over_1lsb,"
           "interior_rel_rms,edge_rms_8bit,edge_max_8bit,edge_over_1lsb,undominated,mc_interior_rms_8bit,"
           "mc_interior_over_1lsb\n";
    md << "# Diffusion profiles: the gather's speed against its accuracy\n\n`shadertwin sweep profile --frames "
       << frames << "` on `" << scene_name << "`: every gather setting on the CPU (" << common.threads
       << " threads) against the exact image, the convolution of the light's spot and half-plane with the "
          "material's profile in double precision (tabulated against distance, read linearly: worst table error "
       << short_number(exact.table_error, 2) << " of the profile's total; " << short_number(exact_s, 3)
       << " s to build). Time: median CPU frame (all passes) over " << frames
       << " rounds, the settings interleaved. Error: 8-bit RGB steps over the interior, the pixels at least "
       << short_number(exact.margin_mm) << " mm inside the slab (where its edge takes less than a thousandth of the "
          "profile's total); the band nearer the edges apart (the slab is finite, the convolution's plane is not). "
          "The gather's reach: " << short_number(exact.reach_mm) << " mm. Settings are `pattern samples @texture size`. **bold**: no other setting "
          "is both faster and more accurate (interior RMS).\n\n";
    md << "Cheapest setting with 99 % of the interior pixels within one 8-bit step: "
       << (cheapest ? "`" + cheapest->setting.label() + "` (" + short_number(cheapest->median_ms) + " ms)" : std::string("none"))
       << ". Images: [exact](profile-sweep-exact.png), [most accurate setting](profile-sweep-best.png) (`"
       << best->setting.label() << "`), [their difference](profile-sweep-best-heat.png).\n\n";
    md << "Against the physics: the same interior against the exact image of the material's Monte Carlo profile ("
       << short_number(mc_document["material"]["mc_r_max_mm"].get<double>()) << " mm of bins): the model's error joins the "
          "gather's, and no sample count takes the image below it.\n\n";
    md << "| setting | CPU ms | interior RMS / max (8-bit) | interior pixels > 1 step | interior rel. RMS (float) | "
          "edge band RMS / max | edge band > 1 step | interior RMS / > 1 step against Monte Carlo |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    // What quality: auto takes for this scene (budget 1): marked when the
    // sweep holds it (the scene's own model, importance sampling, its
    // texture size), else named.
    nlohmann::json auto_document = load_scene(scene_name, common.overrides).document;
    auto_document["quality"] = "auto";
    const QualityChoice auto_choice = measure_quality(backends, scene_name, auto_document, 1);
    const nlohmann::json& as_given = scenes.front().document;
    const std::string scene_model = as_given.contains("material") ? as_given["material"].value("model", std::string()) : "";
    const ProfileResult* auto_result = nullptr;
    for (const ProfileResult& r : results)
        if (auto_choice.model() == scene_model && r.setting.pattern == "importance" &&
            r.setting.samples == auto_choice.samples() &&
            r.setting.texture_size == auto_document.value("geometry", nlohmann::json::object()).value("texture_size", 256))
            auto_result = &r;
    std::string auto_line =
        "`quality: auto` takes " +
        std::string(auto_choice.chosen < 0 ? "(none within the budget: the reference's settings) " : "") +
        auto_choice.model() + " with " + std::to_string(auto_choice.samples()) + " samples";
    double auto_ms = 0, auto_rms = 0;
    if (auto_result) {
        auto_line += " (the black dot).\n";
        auto_ms = auto_result->median_ms, auto_rms = auto_result->interior.rms;
    } else {
        // Another model than the sweep's: rendered as chosen and measured
        // against the Monte Carlo profile's exact image, as the green points.
        const Scene chosen =
            load_scene_document(scene_name, with_choice(auto_document, auto_choice.model(), auto_choice.samples()), "");
        std::vector<double> ms;
        Image image;
        for (int f = 0; f < std::max(frames, 1); ++f) {
            Rendered r = backends.render(Backend::Cpu, chosen.frame);
            ms.push_back(r.ms);
            if (f == 0) image = std::move(r.image);
        }
        const RegionError e = region_error(image, exact_mc, 1);
        auto_ms = median(ms), auto_rms = e.rms;
        auto_line += ", a model these settings do not vary: the black dot is it against the Monte Carlo profile's exact "
                     "image, as the green points (" + short_number(e.rms) + " steps RMS, " +
                     short_number(100 * e.over_1lsb) + " % of the interior over a step, " + short_number(auto_ms) + " ms).\n";
    }
    ChartSeries imp{"importance-sampled", "#1f77b4", {}, {}, false, 2.5}, disk{"uniform disk", "#ff7f0e", {}, {}, false, 2.5},
        front{"undominated", "#d62728", {}, {}, false, 0}, auto_mark{"quality: auto", "#000000", {}, {}, false, 5},
        physics{"importance-sampled, against Monte Carlo", "#2ca02c", {}, {}, false, 2.5};
    std::vector<const ProfileResult*> sorted;
    for (const ProfileResult& r : results) sorted.push_back(&r);
    std::sort(sorted.begin(), sorted.end(), [](const ProfileResult* a, const ProfileResult* b) { return a->median_ms < b->median_ms; });
    for (const ProfileResult* r : sorted) {
        const ProfileSetting& s = r->setting;
        ChartSeries& series = s.pattern == "importance" ? imp : disk;
        series.x.push_back(r->median_ms);
        series.y.push_back(std::max(r->interior.rms, 1e-3));
        if (s.pattern == "importance")
            physics.x.push_back(r->median_ms), physics.y.push_back(std::max(r->physics.rms, 1e-3));
        if (r->undominated) front.x.push_back(r->median_ms), front.y.push_back(std::max(r->interior.rms, 1e-3));
        csv << s.pattern << ',' << s.samples << ',' << s.texture_size << ',' << r->median_ms << ',' << r->interior.rms
            << ',' << r->interior.max << ',' << r->interior.over_1lsb << ',' << r->interior.rel_rms << ','
            << r->edge_band.rms << ',' << r->edge_band.max << ',' << r->edge_band.over_1lsb << ',' << r->undominated << ','
            << r->physics.rms << ',' << r->physics.over_1lsb << '\n';
        const std::string name = r->undominated ? "**" + s.label() + "**" : s.label();
        md << "| " << name << " | " << short_number(r->median_ms) << " | " << short_number(r->interior.rms) << " / "
           << short_number(r->interior.max) << " | " << short_number(100 * r->interior.over_1lsb) << " % | " << short_number(r->interior.rel_rms)
           << " | " << short_number(r->edge_band.rms) << " / " << short_number(r->edge_band.max) << " | "
           << short_number(100 * r->edge_band.over_1lsb) << " % | " << short_number(r->physics.rms) << " / "
           << short_number(100 * r->physics.over_1lsb) << " % |\n";
    }
    Chart chart;
    chart.title = "Diffusion-profile gather: image error against CPU time";
    chart.x_label = "CPU frame, ms (median)";
    chart.y_label = "interior RMS error, 8-bit steps (floored at 1e-3)";
    chart.log_x = chart.log_y = true;
    auto_mark.x.push_back(auto_ms), auto_mark.y.push_back(std::max(auto_rms, 1e-3));
    chart.series = {imp, disk, front, physics, auto_mark};
    write_text_file(out_dir + "/profile-sweep.svg", chart.svg());
    md << "\n![speed against accuracy](profile-sweep.svg)\n\n" << auto_line;
    write_text_file(out_dir + "/profile-sweep.csv", csv.str());
    write_text_file(out_dir + "/profile-sweep.md", md.str());
    std::cout << md.str();
    return ok ? 0 : 1;
}

}  // namespace st
