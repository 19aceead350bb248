// thin_slab_sweep.h: the sample sets of the thin-slab sweeps, shared by the
// "thin-slab-sweep" scene kind (which evaluates them on both backends) and
// the `sweep` command (which checks and charts the results).
#pragma once

#include <string>
#include <vector>

namespace st {

struct SweepSample {
    double x;               // the swept quantity, as charted
    float tau1, mu, mu0;    // model inputs
};

struct SweepRow {
    std::string name;       // e.g. "tau1, mu = mu0 = 1"
    std::string axis;       // what x is: "tau1", "mu", "mu0", "(mu - mu0) / mu0"
    std::vector<SweepSample> samples;
};

// One row per sweep, `samples` samples each (log-spaced).
std::vector<SweepRow> thin_slab_sweep_rows(int samples);

}  // namespace st
