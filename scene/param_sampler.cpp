// param_sampler.cpp: see param_sampler.h.
#include "scene/param_sampler.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace st {

uint64_t SampleRng::next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double SampleRng::uniform() { return double(next() >> 11) * 0x1.0p-53; }

uint64_t SampleRng::below(uint64_t n) { return n ? next() % n : 0; }

namespace {

std::vector<std::string> split(const std::string& path) {
    std::vector<std::string> out;
    size_t start = 0;
    for (;;) {
        const size_t dot = path.find('.', start);
        out.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos) return out;
        start = dot + 1;
    }
}

bool is_index(const std::string& s) {
    return !s.empty() && s.size() <= 9 && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit((unsigned char)c); });
}

// The concrete path of `spec_path` with each "[]" replaced by an index of
// the array in `doc` (drawn), or "" when an array on the way is missing or
// empty. With `like` given, its indices are reused where it has them.
std::string concrete(const std::string& spec_path, const nlohmann::json& doc, SampleRng* rng) {
    std::string out;
    const nlohmann::json* node = &doc;
    for (std::string seg : split(spec_path)) {
        const bool array = seg.size() > 2 && seg.compare(seg.size() - 2, 2, "[]") == 0;
        if (array) seg.resize(seg.size() - 2);
        out += (out.empty() ? "" : ".") + seg;
        node = node && node->is_object() && node->contains(seg) ? &(*node)[seg] : nullptr;
        if (array) {
            if (!node || !node->is_array() || node->empty() || !rng) return "";
            const size_t i = rng->below(node->size());
            out += "." + std::to_string(i);
            node = &(*node)[i];
        }
    }
    return out;
}

std::string text_of(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

}  // namespace

const nlohmann::json* json_at(const nlohmann::json& doc, const std::string& path) {
    const nlohmann::json* node = &doc;
    for (const std::string& seg : split(path)) {
        if (node->is_object()) {
            const auto it = node->find(seg);
            if (it == node->end()) return nullptr;
            node = &*it;
        } else if (node->is_array() && is_index(seg)) {
            const size_t i = std::stoul(seg);
            if (i >= node->size()) return nullptr;
            node = &(*node)[i];
        } else {
            return nullptr;
        }
    }
    return node;
}

bool is_twin_switch(const nlohmann::json* entry) {
    if (!entry || !entry->is_object()) return false;
    const auto name = entry->find("name");
    return name != entry->end() && name->is_string() && name->get<std::string>().rfind("twin_", 0) == 0;
}

void json_set(nlohmann::json& doc, const std::string& path, nlohmann::json value) {
    nlohmann::json* node = &doc;
    for (const std::string& seg : split(path)) {
        if (node->is_array() && is_index(seg) && std::stoul(seg) < node->size()) {
            node = &(*node)[std::stoul(seg)];
        } else {
            if (!node->is_object()) *node = nlohmann::json::object();
            node = &(*node)[seg];
        }
    }
    *node = std::move(value);
}

nlohmann::json ParamSampler::value_or_default(const nlohmann::json& doc, const std::string& path) const {
    if (const nlohmann::json* v = json_at(doc, path)) return *v;
    if (const FieldSpec* f = space_.find(ParamSpace::normalise(path))) return f->fallback;
    return nullptr;
}

namespace {

// The concrete paths of a declared path in `doc`: itself outside arrays,
// else one per entry of each array on the way ("textures[].width" ->
// "textures.0.width", "textures.1.width"), none where an array is absent.
std::vector<std::string> entries_of(const std::string& declared, const nlohmann::json& doc) {
    const size_t hole = declared.find("[]");
    if (hole == std::string::npos) return {declared};
    const std::string array = declared.substr(0, hole);
    const nlohmann::json* a = json_at(doc, array);
    std::vector<std::string> out;
    if (!a || !a->is_array()) return out;
    for (size_t i = 0; i < a->size(); ++i) {
        const std::string entry = array + "." + std::to_string(i);
        for (std::string& p : entries_of(entry + declared.substr(hole + 2), doc)) out.push_back(std::move(p));
    }
    return out;
}

}  // namespace

bool ParamSampler::applies(const FieldSpec& f, const nlohmann::json& doc, const std::string& at) const {
    // A condition inside an array entry ("textures[].pattern") is read in the
    // entry `at` names: its indices take the places of the "[]" in order.
    std::vector<std::string> indices;
    for (const std::string& seg : split(at))
        if (is_index(seg)) indices.push_back(seg);
    const auto in_entry = [&](std::string path) {
        for (const std::string& i : indices) {
            const size_t hole = path.find("[]");
            if (hole == std::string::npos) break;
            path.replace(hole, 2, "." + i);
        }
        return path;
    };
    // The field's own condition and each enclosing object's.
    std::string prefix;
    for (const std::string& seg : split(f.path)) {
        prefix += (prefix.empty() ? "" : ".") + seg;
        std::string declared = prefix;
        if (declared.size() > 2 && declared.compare(declared.size() - 2, 2, "[]") == 0) declared.resize(declared.size() - 2);
        const FieldSpec* g = space_.find(declared);
        if (!g) continue;
        if (g->opaque && g != &f) return false;
        if (!g->when_field.empty()) {
            const std::string v = text_of(value_or_default(doc, in_entry(g->when_field)));
            if (std::find(g->when_values.begin(), g->when_values.end(), v) == g->when_values.end()) return false;
        }
    }
    return true;
}

nlohmann::json ParamSampler::draw_value(const FieldSpec& f, const std::string& path, const nlohmann::json& doc,
                                        SampleRng& rng, bool edge) const {
    (void)path;
    double lo = f.lo, hi = f.hi;
    const auto bound = [&](const std::string& field, double fallback) {
        const nlohmann::json v = value_or_default(doc, field);
        return v.is_number() ? v.get<double>() : fallback;
    };
    if (!f.lo_field.empty()) lo = std::max(lo, bound(f.lo_field, lo));
    if (!f.hi_field.empty()) hi = std::min(hi, bound(f.hi_field, hi));
    if (f.explore_hi > 0) hi = std::min(hi, f.explore_hi);
    if (hi < lo) hi = lo;
    const double draw_lo = std::clamp(f.draw_lo, lo, hi), draw_hi = std::clamp(f.draw_hi, lo, hi);

    const auto number = [&](bool at_edge) -> double {
        if (at_edge) {
            std::vector<double> c = {lo, hi};
            if (lo < hi) c.push_back(std::nextafter(lo, hi)), c.push_back(std::nextafter(hi, lo));
            for (double e : {0.0, 1.0}) c.push_back(e);
            c.insert(c.end(), f.edges.begin(), f.edges.end());
            c.erase(std::remove_if(c.begin(), c.end(), [&](double x) { return !(x >= lo && x <= hi); }), c.end());
            return c[rng.below(c.size())];
        }
        const double u = rng.uniform();
        if (f.log_scale && draw_lo > 0 && draw_hi > draw_lo)
            return std::clamp(std::exp(std::log(draw_lo) + u * (std::log(draw_hi) - std::log(draw_lo))), lo, hi);
        return std::clamp(draw_lo + u * (draw_hi - draw_lo), lo, hi);
    };

    switch (f.type) {
    case FieldType::Number: return number(edge);
    case FieldType::Integer: {
        const long long ilo = (long long)std::ceil(lo), ihi = (long long)std::floor(hi);
        if (edge) {
            std::vector<long long> c = {ilo, ihi, ilo + 1, ihi - 1, 0, 1, 2};
            for (long long p = 4; p <= ihi; p *= 2) c.push_back(p);
            for (double e : f.edges) c.push_back((long long)e);
            c.erase(std::remove_if(c.begin(), c.end(), [&](long long x) { return x < ilo || x > ihi; }), c.end());
            return c[rng.below(c.size())];
        }
        const double x = number(false);
        return std::clamp((long long)std::llround(x), ilo, ihi);
    }
    case FieldType::Boolean: return rng.chance(0.5);
    case FieldType::Choice: {
        const std::vector<std::string>& c = f.drawn_choices.empty() ? f.choices : f.drawn_choices;
        if (!f.max_len) return c[rng.below(c.size())];
        // A list of choices (a blend's factors): as long as the document's.
        const nlohmann::json* v = json_at(doc, path);
        const size_t len = v && v->is_array() && v->size() >= f.min_len && v->size() <= f.max_len ? v->size() : f.min_len;
        nlohmann::json out = nlohmann::json::array();
        for (size_t i = 0; i < len; ++i) out.push_back(c[rng.below(c.size())]);
        return out;
    }
    case FieldType::Numbers: {
        // A row's length as the document has it (a corner given as x, y
        // stays x, y), else the least.
        const nlohmann::json* v = json_at(doc, path);
        const auto length = [&](const nlohmann::json* row) {
            return row && row->is_array() && row->size() >= f.min_len && row->size() <= f.max_len ? row->size() : f.min_len;
        };
        const auto flat = [&](size_t len) {
            nlohmann::json out = nlohmann::json::array();
            for (size_t i = 0; i < len; ++i) {
                const double x = number(edge && rng.chance(0.5));
                if (f.integers)
                    out.push_back((long long)std::clamp(std::round(x), std::ceil(lo), std::floor(hi)));
                else
                    out.push_back(x);
            }
            return out;
        };
        if (!f.rows) return flat(length(v));
        nlohmann::json out = nlohmann::json::array();
        for (size_t r = 0; r < f.rows; ++r)
            out.push_back(flat(length(v && v->is_array() && r < v->size() ? &(*v)[r] : nullptr)));
        return out;
    }
    case FieldType::Text:
    case FieldType::Object: break;
    }
    return nullptr;
}

// A field (or an object around it) declared only_if_present is changed
// only where the document has it: the sampler never adds it. Nor does it
// change anything in an entry named twin_* (a uniform only the twin reads,
// which breaks it on purpose; see is_twin_switch).
bool ParamSampler::present_enough(const std::string& path, const nlohmann::json& doc) const {
    std::string prefix;
    for (const std::string& seg : split(path)) {
        prefix += (prefix.empty() ? "" : ".") + seg;
        const FieldSpec* f = is_index(seg) ? nullptr : space_.find(ParamSpace::normalise(prefix));
        if (f && f->if_present && !json_at(doc, prefix)) return false;
        if (is_index(seg) && is_twin_switch(json_at(doc, prefix))) return false;
    }
    return true;
}

std::vector<Assignment> ParamSampler::draw(const nlohmann::json& base, SampleRng& rng, int max_fields,
                                           double edge_share) const {
    std::vector<const FieldSpec*> candidates;
    for (const FieldSpec& f : space_.fields())
        if (f.explore && f.type != FieldType::Object && f.type != FieldType::Text) candidates.push_back(&f);
    std::vector<Assignment> out;
    if (candidates.empty()) return out;
    nlohmann::json doc = base;
    const int k = 1 + int(rng.below(uint64_t(std::max(1, max_fields))));
    for (int tries = 0; int(out.size()) < k && tries < 50; ++tries) {
        const FieldSpec& f = *candidates[rng.below(candidates.size())];
        const std::string path = concrete(f.path, doc, &rng);
        if (path.empty() || !applies(f, doc, path) || !present_enough(path, doc)) continue;
        if (std::any_of(out.begin(), out.end(), [&](const Assignment& a) { return a.path == path; })) continue;
        nlohmann::json value = draw_value(f, path, doc, rng, rng.chance(edge_share));
        json_set(doc, path, value);
        out.push_back({path, std::move(value)});
    }
    return out;
}

nlohmann::json ParamSampler::apply(const nlohmann::json& base, const std::vector<Assignment>& assignments,
                                   SampleRng& rng) const {
    nlohmann::json doc = base;
    for (const Assignment& a : assignments) json_set(doc, a.path, a.value);

    // Drop what no longer applies (a row's medium after the row changed).
    const auto prune = [&](auto& self, nlohmann::json& node, const std::string& path) -> void {
        if (!node.is_object() && !node.is_array()) return;
        if (node.is_array()) {
            for (size_t i = 0; i < node.size(); ++i) self(self, node[i], path + "." + std::to_string(i));
            return;
        }
        for (auto it = node.begin(); it != node.end();) {
            const std::string p = path.empty() ? it.key() : path + "." + it.key();
            const FieldSpec* f = space_.find(ParamSpace::normalise(p));
            if (f && !applies(*f, doc, p)) {
                it = node.erase(it);
                continue;
            }
            if (!f || !f->opaque) self(self, it.value(), p);
            ++it;
        }
    };
    prune(prune, doc, "");

    // Add what became required (its object first: declaration order), and
    // meet bounds that are other fields' values; a field in array entries
    // in each entry there is (a texture whose pattern became a generated
    // one needs its width).
    for (const FieldSpec& f : space_.fields())
      for (const std::string& path : entries_of(f.path, doc)) {
        if (!applies(f, doc, path)) continue;
        const size_t dot = path.rfind('.');
        const bool parent_present = dot == std::string::npos || json_at(doc, path.substr(0, dot));
        const nlohmann::json* v = json_at(doc, path);
        // A field the explorer may only change where it is (one of several
        // forms: a slab's optics beside a stack) is never added either.
        if (f.required && !v && parent_present && !f.if_present) {
            if (f.type == FieldType::Object)
                json_set(doc, path, nlohmann::json::object());
            else if (f.type != FieldType::Text)
                json_set(doc, path, draw_value(f, path, doc, rng, false));
            continue;
        }
        // The value or, absent, its default: either may be outside a bound
        // another field's new value sets (max_radius's default under a
        // drawn min_radius).
        const nlohmann::json current = v ? *v : f.fallback;
        if (parent_present && current.is_number() && (!f.lo_field.empty() || !f.hi_field.empty())) {
            double x = current.get<double>();
            const nlohmann::json lo = value_or_default(doc, f.lo_field), hi = value_or_default(doc, f.hi_field);
            if (!f.lo_field.empty() && lo.is_number()) x = std::max(x, lo.get<double>());
            if (!f.hi_field.empty() && hi.is_number()) x = std::min(x, hi.get<double>());
            if (x != current.get<double>())
                json_set(doc, path, f.type == FieldType::Integer ? nlohmann::json((long long)std::floor(x)) : nlohmann::json(x));
        }
    }
    return doc;
}

std::vector<Assignment> shrink_assignments(std::vector<Assignment> kept,
                                           const std::function<bool(const std::vector<Assignment>&)>& fails) {
    for (bool dropped = true; dropped && kept.size() > 1;) {
        dropped = false;
        for (size_t j = 0; j < kept.size(); ++j) {
            std::vector<Assignment> fewer = kept;
            fewer.erase(fewer.begin() + long(j));
            if (fails(fewer)) {
                kept = std::move(fewer), dropped = true;
                break;
            }
        }
    }
    return kept;
}

}  // namespace st
