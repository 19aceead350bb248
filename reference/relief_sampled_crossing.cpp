// relief_sampled_crossing.cpp: see relief_sampled_crossing.h.
#include "reference/relief_sampled_crossing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "reference/texel_breakpoints.h"

namespace st::reference {

namespace {

constexpr const char* kWho = "first_sampled_crossing";
constexpr double kMaxBreakpoints = 1e7;
// A ray that stays within its texels' range for thousands of texels (a view
// along the surface) would read steps without end: past this many it is
// refused like a ray with too many texel edges.
constexpr long kMaxStepsRead = 2000000;
// The sampler's texel is (round(256 x) - 128) >> 8: it changes where x
// crosses k + 127.5/256.
constexpr double kTexelEdge = 127.5 / 256;
// A step's byte b reads as b * 0x1.010102p-8 in float, within 1e-7 of
// b / 255: the skip test keeps this much room.
constexpr double kReadSlack = 1e-6;

// One coordinate's steps: X(t) = x0 + t sx is 256 x - 1/2, whose integer
// crossings are where round(256 x) changes.
class StepEdges {
public:
    StepEdges(double x0, double sx) : x0_(x0), sx_(sx) {}
    // The first edge after t.
    void start(double t) {
        if (sx_ == 0) {
            next_ = std::numeric_limits<double>::infinity();
            return;
        }
        const double x = x0_ + t * sx_;
        k_ = sx_ > 0 ? std::floor(x) + 1 : std::ceil(x) - 1;
        next_ = (k_ - x0_) / sx_;
        while (next_ <= t) advance();  // rounding may land on or before t
    }
    void advance() {
        k_ += sx_ > 0 ? 1 : -1;
        next_ = (k_ - x0_) / sx_;
    }
    double next() const { return next_; }

private:
    double x0_, sx_, k_ = 0, next_ = 0;
};

}  // namespace

SampledCrossing first_sampled_crossing(const ReliefHeightField& field, const std::vector<int>& levels,
                                       const SearchRay& ray, const SampledHeights& heights, int batch) {
    const double u0 = ray.u0, v0 = ray.v0, du = ray.du, dv = ray.dv, a = ray.a, dh = ray.dh, side = ray.side;
    for (double x : {u0, v0, du, dv, a, dh})
        if (!std::isfinite(x)) throw std::invalid_argument(std::string(kWho) + ": non-finite input");
    if (side != 1 && side != -1) throw std::invalid_argument(std::string(kWho) + ": side must be 1 or -1");
    if (levels.empty() || batch < 1) throw std::invalid_argument(std::string(kWho) + ": no levels or no batch");
    for (int l : levels)
        if (l < 0 || l >= field.levels()) throw std::invalid_argument(std::string(kWho) + ": no such level");

    const double ur = breakpoints::reduce(u0), vr = breakpoints::reduce(v0);
    // The pieces inside which every level reads the same four texels.
    std::vector<double> ts{0.0, 1.0};
    double budget = kMaxBreakpoints;
    for (int l : levels) {
        const double w = field.level_width(l), h = field.level_height(l);
        breakpoints::add_integer_crossings(ts, budget, ur * w - kTexelEdge, du * w, kWho);
        breakpoints::add_integer_crossings(ts, budget, vr * h - kTexelEdge, dv * h, kWho);
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());

    std::vector<StepEdges> edges;
    for (int l : levels) {
        const double w = field.level_width(l), h = field.level_height(l);
        edges.emplace_back(ur * w * 256 - 0.5, du * w * 256);
        edges.emplace_back(vr * h * 256 - 0.5, dv * h * 256);
    }
    SampledCrossing out;
    // Where the ray meets a step [lo, hi] of height c, if it does: the
    // first s there with f(s) = side (a + dh s - c) <= 0, f being linear.
    bool first_step = true;
    const auto meet = [&](double lo, double hi, double c, double* s) {
        const double f_lo = side * (a + dh * lo - c), f_hi = side * (a + dh * hi - c);
        const bool start = first_step;
        first_step = false;
        if (f_lo <= 0) {
            if (start && ray.leaving) return false;  // the crossing the ray leaves
            *s = lo;
            return true;
        }
        if (f_hi > 0) return false;
        *s = std::clamp((c - a) / dh, lo, hi);  // f_lo > 0 >= f_hi: dh != 0
        return true;
    };
    const size_t n = size_t(batch);
    std::vector<double> step_lo(n), step_hi(n), u(n), v(n);
    std::vector<float> read(n);
    // Reads the pending steps; true (and out.t set) at the first crossing.
    int pending = 0;
    const auto read_pending = [&] {
        heights(u.data(), v.data(), pending, read.data());
        // Step by step, the limit too, so that the batch size changes nothing.
        for (int i = 0; i < pending; ++i) {
            if (++out.steps_read > kMaxStepsRead)
                throw RayTooLong(std::string(kWho) + ": the ray reads more than 2e6 steps of the staircase");
            if (meet(step_lo[size_t(i)], step_hi[size_t(i)], double(read[size_t(i)]), &out.t)) {
                out.hit = true;
                return true;
            }
        }
        pending = 0;
        return false;
    };
    for (size_t k = 0; k + 1 < ts.size(); ++k) {
        const double ta = ts[k], tb = ts[k + 1], tm = 0.5 * (ta + tb);
        // Every read in the piece lies between its texels' lowest and highest
        // (the 8-bit lerps round inside their ends): a ray above the highest
        // (side +1) or under the lowest (side -1) all along it meets nothing.
        double highest = 0, lowest = 1;
        for (int l : levels) {
            const double w = field.level_width(l), h = field.level_height(l);
            const double i = std::floor(ur * w - kTexelEdge + tm * du * w);
            const double j = std::floor(vr * h - kTexelEdge + tm * dv * h);
            for (double y : {j, j + 1})
                for (double x : {i, i + 1}) {
                    const double texel = field.texel(l, breakpoints::wrap_index(x, int(w)), breakpoints::wrap_index(y, int(h)));
                    highest = std::max(highest, texel);
                    lowest = std::min(lowest, texel);
                }
        }
        const double ray_lo = std::min(a + dh * ta, a + dh * tb), ray_hi = std::max(a + dh * ta, a + dh * tb);
        if (side > 0 ? ray_lo > highest + kReadSlack : ray_hi < lowest - kReadSlack) {
            first_step = false;
            continue;
        }
        for (StepEdges& e : edges) e.start(ta);
        for (double t = ta; t < tb;) {
            double end = tb;
            for (const StepEdges& e : edges) end = std::min(end, e.next());
            for (StepEdges& e : edges)
                while (e.next() <= end) e.advance();
            const double mid = 0.5 * (t + end);
            step_lo[size_t(pending)] = t;
            step_hi[size_t(pending)] = end;
            // At the reduced coordinate the steps' edges were found from (the
            // same texels under REPEAT, and a float keeps its precision).
            u[size_t(pending)] = ur + mid * du;
            v[size_t(pending)] = vr + mid * dv;
            if (++pending == batch && read_pending()) return out;
            t = end;
        }
        if (pending > 0 && read_pending()) return out;
    }
    return out;  // no crossing: t = 1, no hit
}

}  // namespace st::reference
