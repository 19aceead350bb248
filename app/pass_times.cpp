// pass_times.cpp: see pass_times.h.
#include "app/pass_times.h"

#include <algorithm>

#include "app/median.h"

namespace st {

namespace {

// The first n passes, then an empty pass into the frame's image so that
// both backends have an image to end on (not for the whole frame).
Frame cut(const Frame& frame, size_t n) {
    Frame f;
    f.targets = frame.targets;
    f.passes.assign(frame.passes.begin(), frame.passes.begin() + long(n));
    if (n < frame.passes.size()) {
        Pass empty;
        empty.width = frame.passes.back().width;
        empty.height = frame.passes.back().height;
        f.passes.push_back(empty);
    }
    return f;
}

}  // namespace

std::vector<PassTime> measure_pass_times(Backends& backends, const Frame& frame, int rounds) {
    const size_t n = frame.passes.size();
    std::vector<Frame> cuts;
    for (size_t k = 0; k <= n; ++k) cuts.push_back(cut(frame, k));
    std::vector<std::vector<double>> cpu(n + 1), gl(n + 1);
    for (int round = 0; round < rounds; ++round)
        for (size_t k = 0; k <= n; ++k) {
            gl[k].push_back(backends.render(Backend::Gl, cuts[k]).ms);
            cpu[k].push_back(backends.render(Backend::Cpu, cuts[k]).ms);
        }
    std::vector<PassTime> out;
    for (size_t k = 1; k <= n; ++k) {
        const std::string& target = frame.passes[k - 1].target;
        out.push_back(PassTime{target.empty() ? "frame" : target, median(cpu[k]) - median(cpu[k - 1]),
                               median(gl[k]) - median(gl[k - 1])});
    }
    return out;
}

}  // namespace st
