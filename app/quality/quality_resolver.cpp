// quality_resolver.cpp: see quality_resolver.h.
#include "app/quality/quality_resolver.h"

#include <functional>
#include <iostream>
#include <stdexcept>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include "app/backends.h"
#include "app/commands.h"
#include "app/quality/profile_quality.h"
#include "app/quality/measured_costs.h"
#include "app/quality/relief_exact.h"
#include "app/quality/relief_quality.h"
#include "app/quality/thin_slab_exact.h"
#include "app/quality/thin_slab_quality.h"
#include "app/short_number.h"
#include "app/tool_data.h"
#include "scene/input_error.h"
#include "scene/profile_cache.h"
#include "scene/scene.h"

namespace st {

namespace {


// The setting a cached relief record names, or nothing when it is not one.
std::optional<ReliefSetting> cached_setting(const nlohmann::json& record) {
    if (!record.is_object()) return std::nullopt;
    if (record.value("setting", std::string()) == "nothing to choose") return ReliefSetting{};
    if (!record.contains("fields") || !record["fields"].is_object()) return std::nullopt;
    const nlohmann::json& f = record["fields"];
    ReliefSetting s;
    try {
        s.linear_steps = f.at("linear_steps").get<int>();
        s.min_linear_steps = f.at("min_linear_steps").get<int>();
        s.binary_steps = f.at("binary_steps").get<int>();
        s.secant = f.at("secant").get<bool>();
        s.planar = f.at("planar").get<bool>();
        s.max_crossings = f.at("max_crossings").get<int>();
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
    return s;
}

// The record cached under `key` when `apply` takes it (writing its choice
// into the document), else `measure`'s, cached then applied; `name` is the
// scene's, for its errors.
nlohmann::json cached_or_measured(const std::string& name, const std::string& key, nlohmann::json& document,
                                  const std::function<bool(const nlohmann::json&, nlohmann::json&)>& apply,
                                  const std::function<nlohmann::json()>& measure) {
    if (const auto cached = load_cached_record(key)) {
        const nlohmann::json record = nlohmann::json::parse(*cached, nullptr, false);
        if (apply(record, document)) return record;
    }
    // The scene as written must stand on its own first: a bad field that the
    // choice would overwrite (a variant or step count out of its domain)
    // is refused, not replaced. (A cached choice was checked when made: the
    // keys' v2 marks records made since this check.)
    load_scene_document(name, without_quality_fields(document), "");
    const nlohmann::json record = measure();
    store_cached_record(key, record.dump());
    if (!apply(record, document)) throw std::logic_error("quality auto: a measured record names no setting");
    return record;
}

nlohmann::json resolve_relief_quality(int threads, const std::string& name, nlohmann::json& document) {
    static const ReliefSweepTwins twins;
    return cached_or_measured(
        name, quality_choice_key("relief quality v3 costs " + measured_costs::fingerprint(), document, relief_quality_budget(document)), document,
        [](const nlohmann::json& record, nlohmann::json& d) {
            const auto s = cached_setting(record);
            if (s) d = with_relief_setting(d, *s);
            return s.has_value();
        },
        [&] { return relief_choice_record(measure_relief_quality(twins, threads, name, document, 3)); });
}

nlohmann::json resolve_thin_slab_quality(int threads, const std::string& name, nlohmann::json& document) {
    static const ThinSlabExactTwins twins;
    return cached_or_measured(
        name, quality_choice_key("thin-slab quality v3 costs " + measured_costs::fingerprint(), document, thin_slab_quality_budget(document)), document,
        [](const nlohmann::json& record, nlohmann::json& d) {
            if (!record.is_object() || !record.contains("fields") || !record["fields"].is_object() ||
                !record["fields"].contains("variant") || !record["fields"]["variant"].is_string())
                return false;
            d = with_thin_slab_variant(d, record["fields"]["variant"].get<std::string>());
            return true;
        },
        [&] { return thin_slab_choice_record(measure_thin_slab_quality(twins, threads, name, document, 3)); });
}

// One line when no candidate met the budget (the most accurate setting is
// used), once per resolution.
void say_if_over(const std::string& name, const nlohmann::json& record) {
    if (record.value("within_budget", true)) return;
    std::cerr << "quality auto: " << name << ": no setting keeps 99 % of the object within "
              << short_number(record.value("budget", kDefaultQualityBudget)) << " 8-bit steps of "
              << record.value("reference", std::string("the reference"));
    if (record.contains("closest") && record["closest"].is_object())
        std::cerr << " (closest: " << record["closest"].value("setting", std::string()) << ", "
                  << short_number(100 * record["closest"].value("over_budget", 0.0)) << " % over)";
    std::cerr << "; using the most accurate, " << record.value("setting", std::string()) << "\n";
}

}  // namespace

void install_quality_resolver(int threads, GlPlatform gl_platform) {
    set_quality_resolver([threads, gl_platform](const std::string& name, nlohmann::json& document) {
        const auto kind = document.find("kind");
        const std::string k = kind != document.end() && kind->is_string() ? kind->get<std::string>() : "";
        nlohmann::json record;
        if (k == "profile") {
            static std::mutex mutex;
            static std::unique_ptr<Backends> backends;
            std::lock_guard<std::mutex> lock(mutex);
            if (!backends) backends = std::make_unique<Backends>(threads, gl_platform, glsl_roots());
            record = resolve_profile_quality(*backends, name, document);
        } else if (k == "relief") {
            static std::mutex mutex;
            std::lock_guard<std::mutex> lock(mutex);
            record = resolve_relief_quality(threads, name, document);
        } else if (k == "thin-slab") {
            static std::mutex mutex;
            std::lock_guard<std::mutex> lock(mutex);
            record = resolve_thin_slab_quality(threads, name, document);
        } else {
            throw InputError("field 'quality': \"auto\" chooses a profile, relief or thin-slab scene's settings; a " +
                             (k.empty() ? std::string("scene without a kind") : k + " scene") +
                             " has none to choose");
        }
        say_if_over(name, record);
        return record;
    });
}

std::string quality_summary(const nlohmann::json& q) {
    std::ostringstream o;
    o << "quality auto: " << q.value("setting", std::string("?"));
    if (q.contains("over_budget"))
        o << " (" << short_number(100 * q.value("over_budget", 0.0)) << " % of the object over "
          << short_number(q.value("budget", 1.0)) << " steps, p99 " << short_number(q.value("p99_8bit", 0.0))
          << ", max " << short_number(q.value("max_8bit", 0.0)) << ")";
    else if (!q.value("within_budget", true))
        o << " (none within the budget: the most accurate)";
    if (q.contains("cpu_ms"))
        o << "; CPU " << short_number(q.value("cpu_ms", 0.0)) << " ms, the most accurate "
          << short_number(q.value("most_accurate_cpu_ms", 0.0)) << " ms when measured";
    return o.str();
}

}  // namespace st
