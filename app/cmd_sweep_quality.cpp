// cmd_sweep_quality.cpp: `sweep profile-quality`, the table behind
// `quality: auto` (app/quality/profile_quality.h): for each diffusion-profile scene,
// every candidate tried (model, sample count), its error against the Monte
// Carlo reference and its measured frame time, and the choice. Writes
// Markdown and a CSV.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/tool_data.h"
#include "app/progress.h"
#include "app/memory_budget.h"
#include "app/backends.h"
#include "app/commands.h"
#include "app/quality/profile_quality.h"
#include "app/short_number.h"
#include "image/image_io.h"
#include "scene/input_error.h"
#include "scene/profile_material.h"
#include "scene/scene.h"

namespace st {

int cmd_sweep_quality(const std::vector<std::string>& scene_names, const std::string& out_dir, int frames,
                      const CommonOptions& common) {
    std::vector<std::string> names = scene_names;
    if (names.empty())
        for (const std::string& n : builtin_scene_names())
            if (n.rfind("profile-", 0) == 0) names.push_back(n);
    // Every scene read first: bad input stops the sweep before it writes.
    std::vector<Scene> scenes;
    for (const std::string& n : names) {
        scenes.push_back(load_scene(n, common.overrides));
        if (scenes.back().kind != "profile") throw InputError("sweep profile-quality: '" + n + "' is not a profile scene");
    }
    check_memory(scenes, MemoryUse::Compare, common.max_memory);
    if (!out_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(out_dir, ec);
        if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());
    }
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    std::ostringstream md, csv;
    md << "# Diffusion profiles: the cheapest model and sample count per scene\n\n`shadertwin sweep profile-quality "
          "--frames "
       << frames << "`, CPU, " << common.threads
       << " threads. Reference: the scene's material with its Monte Carlo profile, gathered with " << kReferenceSamples
       << " samples, its bins reaching 7 diffusion lengths 1 / sigma_tr of the material's most penetrating "
          "channel (at least 20 mm). Budget: at most " << short_number(100 * kOverBudgetShare)
       << " % of the object's pixels more than one 8-bit step off the reference in any channel. Candidates in order of "
          "cost (fewer samples first; at equal samples dipole, then multipole, then layered, by profile build time; "
          "the Monte Carlo profile with fewer samples only when no diffusion model meets the budget); "
          "the first within the budget is what `--set quality=auto` renders. Frame times: medians of "
       << frames << " CPU frames.\n\n"
       << "| scene | choice | its frame ms | reference frame ms (bins' reach, mm) | tried: model samples (share of "
          "pixels over budget, p99 / max steps) |\n| --- | --- | --- | --- | --- |\n";
    csv << "scene,model,samples,frame_ms,over_budget,p99_8bit,max_8bit,within,chosen,build\n";
    bool failures = false;
    Progress progress("sweep profile-quality", scenes.size());
    for (const Scene& s : scenes) {
        nlohmann::json document = s.document;
        document["quality"] = "auto";
        QualityChoice c;
        try {
            c = measure_quality(backends, s.name, document, frames);
        } catch (const InputError& e) {
            // The scene itself loaded: what failed is its reference or a
            // candidate's profile. Say so in its row and go on.
            md << "| " << s.name << " | cannot be measured: " << e.what() << " | | | |\n";
            std::cerr << "sweep profile-quality: " << s.name << ": cannot be measured: " << e.what() << "\n";
            failures = true;
            continue;
        }
        remember_quality_choice(document, c);  // what `--set quality=auto` then renders without measuring
        std::ostringstream tried;
        for (size_t i = 0; i < c.tried.size(); ++i) {
            const QualityCandidate& t = c.tried[i];
            if (i) tried << "; ";
            if (!t.not_applicable.empty()) {
                tried << t.model << ": does not apply (" << t.not_applicable << ")";
                continue;
            }
            const bool chosen = int(i) == c.chosen;
            tried << (chosen ? "**" : "") << t.model << ' ' << t.samples << " (" << short_number(100 * t.over_budget, 2)
                  << " %, " << short_number(t.p99) << " / " << short_number(t.max) << ")" << (chosen ? "**" : "");
            csv << s.name << ',' << t.model << ',' << t.samples << ',' << t.frame_ms << ',' << t.over_budget << ','
                << t.p99 << ',' << t.max << ',' << t.within << ',' << chosen << ",\"" << t.build_source << "\"\n";
        }
        const std::string choice = c.chosen < 0 ? "none within budget: mc " + std::to_string(kReferenceSamples)
                                                : c.model() + " " + std::to_string(c.samples());
        md << "| " << s.name << " | " << choice << " | "
           << (c.chosen < 0 ? short_number(c.reference_ms) : short_number(c.tried[size_t(c.chosen)].frame_ms)) << " | "
           << short_number(c.reference_ms) << " (" << short_number(c.reference_reach_mm) << ") | " << tried.str() << " |\n";
        progress.step(s.name + ": " + choice);
    }
    md << "\nEach candidate's profile build (model, source, time; not in any frame) is in the CSV's last column.\n";
    if (!out_dir.empty()) {
        write_text_file(out_dir + "/profile-quality.md", md.str());
        write_text_file(out_dir + "/profile-quality.csv", csv.str());
    }
    std::cout << md.str();
    return failures ? 1 : 0;
}

}  // namespace st
