// explore.cpp: `shadertwin explore` (see explore.h). Each case is a base
// scene of a kind plus a few fields drawn by scene/param_sampler.h; it is
// loaded (a refusal is an answer, counted by message), compared on both
// backends, and, when it fails, shrunk: drop one drawn field at a time and
// keep the drop while the case still fails. Case i's draws depend on the
// seed and i only, so a summary's case can be drawn again.
#include "app/commands/explore.h"

#include <chrono>
#include <iomanip>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "app/backends.h"
#include "app/comparison.h"
#include "app/json_text.h"
#include "app/memory_budget.h"
#include "app/progress.h"
#include "app/tool_data.h"
#include "raster/cpu_renderer.h"
#include "scene/input_error.h"
#include "scene/json_reader.h"
#include "scene/param_sampler.h"
#include "scene/scene.h"
#include "scene/scene_sources.h"

namespace st {

namespace fs = std::filesystem;

namespace {

struct Base {
    std::string name;
    nlohmann::json document;
};

// A drawn blend on a scene whose NaNs must match bit for bit
// (criteria.nonfinite "identical") makes two NaNs meet in one blend, whose
// payload is the operand order LLVM emitted (docs/scenes.md, criteria;
// docs/llvmpipe/render-targets-and-blending.md): the bound is then
// "nan_any_payload", as a scene that blends NaNs on purpose states it. A NaN
// against a number still fails.
void bound_drawn_blend(nlohmann::json& doc) {
    bool blends = doc.contains("blend") && !doc["blend"].is_null();
    if (doc.contains("passes") && doc["passes"].is_array())
        for (const nlohmann::json& p : doc["passes"]) blends = blends || (p.is_object() && p.contains("blend") && !p["blend"].is_null());
    if (!blends || !doc.contains("criteria") || !doc["criteria"].is_object()) return;
    nlohmann::json& criteria = doc["criteria"];
    if (criteria.value("nonfinite", std::string("none")) != "identical") return;
    criteria["nonfinite"] = "nan_any_payload";
    criteria["rationale"] = criteria.value("rationale", std::string()) +
                            " (explore: the drawn blend lets two NaNs meet, whose payload is LLVM's operand order)";
}

enum class Outcome { Pass, Fail, Refused, Error };

struct CaseResult {
    Outcome outcome = Outcome::Pass;
    std::string message;                 // refusal or error text, first failure
    std::vector<std::string> failures;   // the comparison's
};

struct KindCount {
    long cases = 0, pass = 0, fail = 0, refused = 0, errors = 0;
    std::map<std::string, long> refusals;  // message (without the scene's name) -> count
    double seconds = 0;                    // the cases' time, shrinking included
    long slowest_case = -1;                // where a long run's time goes
    double slowest_seconds = 0;
    std::string slowest_drawn;
};

nlohmann::json read_document(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot read scene file " + path);
    nlohmann::json doc = parse_json(in, path);
    if (doc.is_discarded() || !doc.is_object()) throw InputError(path + ": not a JSON object");
    return doc;
}

std::string document_kind(const nlohmann::json& doc, const std::string& where) {
    if (!doc.contains("kind") || !doc["kind"].is_string()) throw InputError(where + ": no kind");
    return doc["kind"].get<std::string>();
}

// The base scenes per kind: the targets' scenes, or every built-in scene of
// each target kind.
std::map<std::string, std::vector<Base>> bases_of(const std::vector<std::string>& targets,
                                                  const std::vector<std::string>& overrides) {
    std::vector<std::string> wanted = targets;
    if (wanted.empty()) wanted = spaced_kinds();
    std::map<std::string, std::vector<Base>> out;
    for (const std::string& t : wanted) {
        std::vector<std::pair<std::string, std::string>> files;  // name, path
        if (kind_space(t)) {
            for (const SceneEntry& e : scene_sources().entries())
                if (document_kind(read_document(e.path), e.path) == t) files.push_back({e.name, e.path});
            if (files.empty()) throw InputError("explore: no built-in scene of kind '" + t + "' to start from");
        } else if (t.find('/') != std::string::npos || fs::path(t).extension() == ".json") {
            files.push_back({fs::path(t).stem().string(), t});
        } else if (const auto e = scene_sources().find(t)) {
            files.push_back({e->name, e->path});
        } else {
            throw InputError("explore: '" + t + "' is neither a scene kind with a declared space nor a scene");
        }
        for (const auto& [name, path] : files) {
            nlohmann::json doc = read_document(path);
            const std::string kind = document_kind(doc, path);
            if (!kind_space(kind)) throw InputError("explore: scene kind '" + kind + "' (" + name + ") declares no parameter space");
            for (const std::string& o : overrides) apply_override(doc, o);
            // Absolute, so that a reproducer written anywhere finds them.
            resolve_scene_paths(doc, fs::absolute(path).parent_path().string());
            out[kind].push_back({name, std::move(doc)});
        }
    }
    return out;
}

// Case i's generator: the seed and i mixed, so that cases are independent
// of how many came before and of --time.
SampleRng case_rng(uint64_t seed, long i, uint64_t stream) {
    SampleRng mix(seed ^ (uint64_t(i) * 0xD1B54A32D192ED03ull) ^ (stream * 0x8CB92BA72F3D8DD7ull));
    return SampleRng(mix.next());
}

class Explorer {
public:
    Explorer(const ExploreOptions& options, const CommonOptions& common)
        : options_(options), common_(common),
          backends_(common.threads, common.gl_platform, glsl_roots()) {}

    CaseResult run(const std::string& name, const nlohmann::json& doc, const std::string& out_dir) {
        CaseResult r;
        Scene scene;
        try {
            scene = load_scene_document(name, doc, "");
            check_memory({scene}, MemoryUse::Compare, common_.max_memory);
        } catch (const InputError& e) {
            r.outcome = Outcome::Refused, r.message = e.what();
            return r;
        }
        try {
            fs::create_directories(out_dir);
            const SceneComparison c = compare_scene(scene, backends_, out_dir, CompareFiles{false, true});
            if (!c.pass()) {
                r.outcome = Outcome::Fail;
                r.failures = c.failures;
                for (const auto& o : c.outputs)
                    for (const auto& f : o.failures) r.failures.push_back(o.name + ": " + f);
                r.message = r.failures.empty() ? "failed" : r.failures.front();
            }
        } catch (const UnrenderableInput& e) {
            // A refusal the renderer can only make once the vertex twin has
            // run (the reader does not see where a vertex lands).
            r.outcome = Outcome::Refused, r.message = e.what();
        } catch (const std::exception& e) {
            r.outcome = Outcome::Error, r.message = e.what();
        }
        return r;
    }

    static bool failing(const CaseResult& r) { return r.outcome == Outcome::Fail || r.outcome == Outcome::Error; }

private:
    const ExploreOptions& options_;
    const CommonOptions& common_;
    Backends backends_;
};

nlohmann::json assignments_json(const std::vector<Assignment>& as) {
    nlohmann::json j = nlohmann::json::object();
    for (const Assignment& a : as) j[a.path] = a.value;
    return j;
}

std::string assignments_text(const std::vector<Assignment>& as) {
    std::string out;
    for (const Assignment& a : as) out += (out.empty() ? "" : ", ") + a.path + "=" + a.value.dump();
    return out;
}

const char* outcome_name(Outcome o) {
    switch (o) {
    case Outcome::Pass: return "pass";
    case Outcome::Fail: return "fail";
    case Outcome::Refused: return "refused";
    case Outcome::Error: return "error";
    }
    return "?";
}

}  // namespace

int cmd_explore(const ExploreOptions& options, const CommonOptions& common) {
    if (options.cases < 1) throw InputError("--cases must be at least 1");
    if (!(options.seconds >= 0)) throw InputError("--time must be a number of seconds >= 0");
    if (options.max_fields < 1 || options.max_fields > 32) throw InputError("--fields must be 1 to 32");
    const auto bases = bases_of(options.targets, common.overrides);
    std::vector<std::string> kinds;
    for (const auto& [k, b] : bases) kinds.push_back(k);

    fs::create_directories(options.out_dir);
    const fs::path cases_dir = fs::path(options.out_dir) / "cases", repro_dir = fs::path(options.out_dir) / "reproducers";
    fs::remove_all(cases_dir);
    Explorer explorer(options, common);
    Progress progress("explore", size_t(options.cases));
    std::map<std::string, KindCount> counts;
    nlohmann::json failures = nlohmann::json::array();
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    long run = 0;
    double last_written = 0;
    // The summary, also written every minute while the run goes on, so a
    // long run stopped early still says what it found ("finished": false).
    long bad = 0;
    const auto summary_json = [&](bool finished) {
        nlohmann::json summary = {{"seed", options.seed}, {"cases", run}, {"seconds", elapsed()},
                                  {"max_fields", options.max_fields}, {"finished", finished}};
        if (!common.overrides.empty()) summary["set"] = common.overrides;
        nlohmann::json per_kind = nlohmann::json::object();
        bad = 0;
        for (const auto& [kind, c] : counts) {
            nlohmann::json refusals = nlohmann::json::object();
            for (const auto& [m, n] : c.refusals) refusals[m] = n;
            per_kind[kind] = {{"cases", c.cases}, {"pass", c.pass},       {"fail", c.fail},
                              {"refused", c.refused}, {"errors", c.errors}, {"refusals", refusals},
                              {"seconds", c.seconds}};
            if (c.slowest_case >= 0)
                per_kind[kind]["slowest"] = {{"case", c.slowest_case}, {"seconds", c.slowest_seconds},
                                             {"drawn", c.slowest_drawn}};
            bad += c.fail + c.errors;
        }
        summary["kinds"] = per_kind;
        summary["failures"] = failures;
        const fs::path path = fs::path(options.out_dir) / "summary.json", tmp = path.string() + ".tmp";
        {
            std::ofstream out(tmp);
            out << json_text(summary) << "\n";
            if (!out) throw std::runtime_error("cannot write " + path.string());
        }
        fs::rename(tmp, path);
        return summary;
    };
    for (long i = 0; i < options.cases; ++i) {
        if (options.seconds > 0 && elapsed() >= options.seconds) break;
        const std::string& kind = kinds[size_t(i) % kinds.size()];
        const ParamSampler sampler(*kind_space(kind));
        SampleRng rng = case_rng(options.seed, i, 0);
        const Base& base = bases.at(kind)[rng.below(bases.at(kind).size())];
        const std::vector<Assignment> drawn = sampler.draw(base.document, rng, options.max_fields);
        // The fields apply() adds are drawn from a generator of their own,
        // the same for every shrinking step.
        const auto document = [&](const std::vector<Assignment>& as) {
            SampleRng fill = case_rng(options.seed, i, 1);
            nlohmann::json doc = sampler.apply(base.document, as, fill);
            bound_drawn_blend(doc);
            return doc;
        };
        const std::string name = "case-" + std::to_string(i);
        progress.step(kind + " " + base.name + " " + assignments_text(drawn));
        const fs::path dir = cases_dir / name;
        const double case_start = elapsed();
        CaseResult r = explorer.run(name, document(drawn), dir.string());
        ++run;
        KindCount& c = counts[kind];
        ++c.cases;
        // (The first run only: shrinking below adds to `seconds`, not here.)
        if (const double t = elapsed() - case_start; t > c.slowest_seconds)
            c.slowest_case = i, c.slowest_seconds = t, c.slowest_drawn = base.name + " with " + assignments_text(drawn);
        switch (r.outcome) {
        case Outcome::Pass: ++c.pass; break;
        case Outcome::Refused: ++c.refused, ++c.refusals[r.message]; break;
        case Outcome::Fail: ++c.fail; break;
        case Outcome::Error: ++c.errors; break;
        }
        if (elapsed() - last_written >= 60) summary_json(false), last_written = elapsed();
        if (!Explorer::failing(r)) {
            fs::remove_all(dir);
            c.seconds += elapsed() - case_start;
            continue;
        }
        // Shrink: drop one field at a time while the case still fails.
        CaseResult last = r;
        const std::vector<Assignment> kept = shrink_assignments(drawn, [&](const std::vector<Assignment>& fewer) {
            progress.note("shrinking to " + std::to_string(fewer.size()) + " fields");
            fs::remove_all(dir);
            const CaseResult s = explorer.run(name, document(fewer), dir.string());
            if (!Explorer::failing(s)) return false;
            last = s;
            return true;
        });
        // The images left are the shrunk case's (the last attempt may have
        // passed and taken its folder with it).
        if (drawn.size() > 1) {
            fs::remove_all(dir);
            explorer.run(name, document(kept), dir.string());
        }
        // The reproducer: the whole scene, its story in its description.
        nlohmann::json repro = document(kept);
        repro["description"] = "Found by shadertwin explore --seed " + std::to_string(options.seed) + " (case " +
                               std::to_string(i) + "): " + base.name + " with " + assignments_text(kept) + "; " +
                               outcome_name(last.outcome) + ": " + last.message;
        fs::create_directories(repro_dir);
        const fs::path repro_path = repro_dir / (kind + "-case-" + std::to_string(i) + ".json");
        {
            const fs::path tmp = repro_path.string() + ".tmp";
            std::ofstream out(tmp);
            out << repro.dump(1) << "\n";
            out.close();
            if (!out) throw std::runtime_error("cannot write " + repro_path.string());
            fs::rename(tmp, repro_path);
        }
        failures.push_back({{"case", i},
                            {"kind", kind},
                            {"base", base.name},
                            {"drawn", assignments_json(drawn)},
                            {"shrunk", assignments_json(kept)},
                            {"outcome", outcome_name(last.outcome)},
                            {"failures", last.outcome == Outcome::Error ? std::vector<std::string>{last.message} : last.failures},
                            {"reproducer", repro_path.string()},
                            {"images", dir.string()}});
        c.seconds += elapsed() - case_start;
    }

    const nlohmann::json summary = summary_json(true);
    if (options.json) {
        std::cout << json_text(summary) << std::endl;
    } else {
        for (const auto& [kind, c] : counts)
            std::cout << kind << ": " << c.cases << " cases, " << c.pass << " pass, " << c.fail << " fail, "
                      << c.errors << " errors, " << c.refused << " refused\n";
        for (const auto& f : failures)
            std::cout << "FAIL case " << f["case"] << " (" << f["base"].get<std::string>() << ", "
                      << f["shrunk"].dump() << "): " << f["failures"][0].get<std::string>() << "\n    reproduce: shadertwin compare "
                      << f["reproducer"].get<std::string>() << "\n";
        std::cout << run << " cases in " << std::fixed << std::setprecision(1) << elapsed() << " s; summary: "
                  << (fs::path(options.out_dir) / "summary.json").string() << "\n";
    }
    return bad ? 1 : 0;
}

}  // namespace st
