// measured_costs.h: the frame times that order `quality: auto`'s candidates
// (issue 28: cheapest is measured, not assumed), taken from the sweeps' own
// runs: `sweep relief` (docs/relief-sweep/relief-sweep.csv, every search
// candidate at five view angles) and `sweep thin-slab` (docs/thin-slab-
// speed/thin-slab-speed.csv, each variant at six flag meshes on three light
// paths). The CSVs are compiled in (app/CMakeLists.txt), so the order is
// the one measured where they were made, and the same on every machine that
// runs this build: errors decide, these times only order the candidates.
// Re-running a sweep (on any machine) and rebuilding re-measures it; the
// choice cache's key holds fingerprint(), so older choices are not reused.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace st {

struct ReliefSetting;

namespace measured_costs {

// A relief search setting's median CPU frame (ms) in `sweep relief` at
// `angle_deg`: linear between the sweep's two nearest angles, the nearest
// one's outside its range. std::logic_error when the table lacks the
// setting (a candidate added without re-running the sweep).
double relief_search_ms(const ReliefSetting& setting, double angle_deg);

// A thin-slab variant's median CPU frame (ms) in `sweep thin-slab` at the
// measured flag mesh nearest to `quads` (on a log scale; the smaller at a
// tie), averaged over the light paths. std::logic_error when the table
// lacks the variant.
double thin_slab_variant_ms(const std::string& variant, double quads);

// What the tables were measured with (their "# made by" lines, for the
// records) and a hash of their contents (for the cache keys).
std::string provenance();
std::string fingerprint();

// A time as the sweeps write it to their CSVs (six significant digits): a
// sweep orders auto's candidates by these, as the build will.
double as_written(double ms);

// The parsers behind the above, for tests: rows of (angle, linear steps,
// min linear steps, binary steps, secant, ms) and of (light path, columns,
// rows, variant, ms). std::invalid_argument for a malformed table.
struct ReliefRow {
    double angle_deg;
    int linear_steps, min_linear_steps, binary_steps;
    bool secant;
    double ms;
};
struct ThinSlabRow {
    std::string path;
    int columns, rows;
    std::string variant;
    double ms;
};
std::vector<ReliefRow> parse_relief_table(const std::string& csv);
std::vector<ThinSlabRow> parse_thin_slab_table(const std::string& csv);
double relief_search_ms(const std::vector<ReliefRow>& table, const ReliefSetting& setting, double angle_deg);
double thin_slab_variant_ms(const std::vector<ThinSlabRow>& table, const std::string& variant, double quads);

}  // namespace measured_costs
}  // namespace st
