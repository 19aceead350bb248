// measured_costs.cpp: see measured_costs.h.
#include "app/quality/measured_costs.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include "app/quality/relief_quality.h"

namespace st::measured_costs {

namespace data {
extern const char* const kReliefSweep;
extern const char* const kThinSlabSpeed;
}  // namespace data

namespace {

// A CSV's "# made by" lines, its header's column indices and its rows.
struct Csv {
    std::vector<std::string> comments;
    std::map<std::string, size_t> column;
    std::vector<std::vector<std::string>> rows;
    const std::string& at(const std::vector<std::string>& row, const std::string& name) const {
        const auto it = column.find(name);
        if (it == column.end() || it->second >= row.size())
            throw std::invalid_argument("cost table: no column '" + name + "'");
        return row[it->second];
    }
};

Csv read_csv(const std::string& text) {
    Csv csv;
    std::istringstream in(text);
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (line[0] == '#') {
            csv.comments.push_back(line);
            continue;
        }
        std::vector<std::string> cells;
        std::istringstream cells_in(line);
        for (std::string cell; std::getline(cells_in, cell, ',');) cells.push_back(cell);
        if (header) {
            for (size_t i = 0; i < cells.size(); ++i) csv.column[cells[i]] = i;
            header = false;
        } else {
            csv.rows.push_back(std::move(cells));
        }
    }
    if (header) throw std::invalid_argument("cost table: no header");
    return csv;
}

double number(const std::string& s) {
    size_t used = 0;
    double x = 0;
    try {
        x = std::stod(s, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != s.size() || !std::isfinite(x)) throw std::invalid_argument("cost table: not a number: '" + s + "'");
    return x;
}
int integer(const std::string& s) {
    const double x = number(s);
    if (x != std::floor(x) || std::abs(x) > 1e9) throw std::invalid_argument("cost table: not an integer: '" + s + "'");
    return int(x);
}

const std::vector<ReliefRow>& relief_table() {
    static const std::vector<ReliefRow> table = parse_relief_table(data::kReliefSweep);
    return table;
}
const std::vector<ThinSlabRow>& thin_slab_table() {
    static const std::vector<ThinSlabRow> table = parse_thin_slab_table(data::kThinSlabSpeed);
    return table;
}

}  // namespace

std::vector<ReliefRow> parse_relief_table(const std::string& text) {
    const Csv csv = read_csv(text);
    std::vector<ReliefRow> out;
    for (const auto& row : csv.rows)
        out.push_back(ReliefRow{number(csv.at(row, "angle_deg")), integer(csv.at(row, "linear_steps")),
                                integer(csv.at(row, "min_linear_steps")), integer(csv.at(row, "binary_steps")),
                                integer(csv.at(row, "secant")) != 0, number(csv.at(row, "cpu_ms_median"))});
    return out;
}

std::vector<ThinSlabRow> parse_thin_slab_table(const std::string& text) {
    const Csv csv = read_csv(text);
    std::vector<ThinSlabRow> out;
    for (const auto& row : csv.rows)
        out.push_back(ThinSlabRow{csv.at(row, "light"), integer(csv.at(row, "columns")), integer(csv.at(row, "rows")),
                                  csv.at(row, "variant"), number(csv.at(row, "cpu_ms_median"))});
    return out;
}

double relief_search_ms(const std::vector<ReliefRow>& table, const ReliefSetting& s, double angle_deg) {
    std::map<double, double> by_angle;  // this setting's rows
    for (const ReliefRow& r : table)
        if (r.linear_steps == s.linear_steps && r.min_linear_steps == s.min_linear_steps &&
            r.binary_steps == s.binary_steps && r.secant == s.secant)
            by_angle[r.angle_deg] = r.ms;
    if (by_angle.empty())
        throw std::logic_error("quality auto: sweep relief measured no '" + s.label() +
                               "' (re-run it: docs/relief-sweep/relief-sweep.csv)");
    const auto above = by_angle.lower_bound(angle_deg);
    if (above == by_angle.begin()) return above->second;
    if (above == by_angle.end()) return std::prev(above)->second;
    const auto below = std::prev(above);
    const double f = (angle_deg - below->first) / (above->first - below->first);
    return below->second + f * (above->second - below->second);
}

double thin_slab_variant_ms(const std::vector<ThinSlabRow>& table, const std::string& variant, double quads) {
    std::map<std::pair<int, int>, std::pair<double, int>> by_mesh;  // (columns, rows) -> sum, count
    for (const ThinSlabRow& r : table)
        if (r.variant == variant) {
            auto& [sum, n] = by_mesh[{r.columns, r.rows}];
            sum += r.ms;
            ++n;
        }
    if (by_mesh.empty())
        throw std::logic_error("quality auto: sweep thin-slab measured no '" + variant +
                               "' variant (re-run it: docs/thin-slab-speed/thin-slab-speed.csv)");
    const double log_quads = std::log(std::max(1.0, quads));
    double best = 0, best_distance = INFINITY, best_quads = 0;
    for (const auto& [mesh, sum_n] : by_mesh) {
        const double q = double(mesh.first) * double(mesh.second);
        const double distance = std::abs(std::log(std::max(1.0, q)) - log_quads);
        if (distance < best_distance || (distance == best_distance && q < best_quads))
            best = sum_n.first / sum_n.second, best_distance = distance, best_quads = q;
    }
    return best;
}

double relief_search_ms(const ReliefSetting& setting, double angle_deg) {
    return relief_search_ms(relief_table(), setting, angle_deg);
}

double thin_slab_variant_ms(const std::string& variant, double quads) {
    return thin_slab_variant_ms(thin_slab_table(), variant, quads);
}

std::string provenance() {
    std::string out;
    for (const char* text : {data::kReliefSweep, data::kThinSlabSpeed}) {
        const Csv csv = read_csv(text);
        if (!csv.comments.empty()) out += (out.empty() ? "" : "; ") + csv.comments.front().substr(1);
    }
    return out;
}

std::string fingerprint() {
    // FNV-1a over both tables: stable across builds and machines.
    uint64_t h = 14695981039346656037ull;
    for (const char* text : {data::kReliefSweep, data::kThinSlabSpeed})
        for (const char* p = text; *p; ++p) h = (h ^ uint8_t(*p)) * 1099511628211ull;
    std::ostringstream s;
    s << std::hex << std::setw(16) << std::setfill('0') << h;
    return s.str();
}

double as_written(double ms) {
    std::ostringstream s;
    s << ms;  // the CSVs' default stream format
    return std::stod(s.str());
}

}  // namespace st::measured_costs
