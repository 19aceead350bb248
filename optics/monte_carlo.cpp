// monte_carlo.cpp: see monte_carlo.h. Follows MCML's steps (Wang et al.
// 1995, the MCML manual ch. 3-4): all-or-none Fresnel at interfaces, the
// unfinished step length carried across an interface, roulette below weight
// 1e-4 with survival chance 0.1.
#include "optics/monte_carlo.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <system_error>
#include <thread>

#include "optics/photon_rng.h"
#include "optics/microsurface_walk.h"
#include "optics/rough_surface.h"

namespace st::optics {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCosZero = 1.0 - 1e-12;
constexpr double kCos90 = 1e-6;
constexpr double kRouletteWeight = 1e-4;
constexpr double kRouletteChance = 0.1;

struct Tally {
    double R = 0, T = 0, T_direct = 0, absorbed = 0, specular = 0;
    std::vector<double> R_bins, T_bins;
};

// Unpolarised Fresnel reflectance from medium n1 into n2 at incidence cosine
// ca1 (> 0); ca2 receives the cosine of the transmitted direction.
double fresnel(double n1, double n2, double ca1, double& ca2) {
    if (n1 == n2) {
        ca2 = ca1;
        return 0.0;
    }
    if (ca1 > kCosZero) {
        ca2 = ca1;
        const double r = (n2 - n1) / (n2 + n1);
        return r * r;
    }
    if (ca1 < kCos90) {
        ca2 = 0.0;
        return 1.0;
    }
    const double sa1 = std::sqrt(1.0 - ca1 * ca1);
    const double sa2 = n1 * sa1 / n2;
    if (sa2 >= 1.0) {  // total internal reflection
        ca2 = 0.0;
        return 1.0;
    }
    ca2 = std::sqrt(1.0 - sa2 * sa2);
    const double cap = ca1 * ca2 - sa1 * sa2, cam = ca1 * ca2 + sa1 * sa2;
    const double sap = sa1 * ca2 + ca1 * sa2, sam = sa1 * ca2 - ca1 * sa2;
    return 0.5 * sam * sam * (cam * cam + cap * cap) / (sap * sap * cam * cam);
}

// A photon with direction (ux, uy, uz) meets a rough interface z = const from
// index n1 into n2. Samples a Beckmann facet normal h with density
// D(h) (h.n) on the photon's side, reflects with probability F(i.h) or
// refracts through h, and multiplies the weight by |i.h| G / (|i.n| |h.n|)
// (Walter et al. 2007, Eq. 41, with the Torrance-Sparrow G of Eq. 23).
// Returns true when the photon ends on the far side (transmitted); a
// direction that the facet sends into the wrong half-space ends the photon
// (w = 0), the energy the single-scattering facet model loses.
bool rough_interface(double m, double n1, double n2, double& ux, double& uy, double& uz, double& w, PhotonRng& rng) {
    const double side = uz > 0.0 ? -1.0 : 1.0;  // normal on the photon's side: (0, 0, side)
    const double ix = -ux, iy = -uy, iz = -uz;  // towards where it came from
    double hx = 0, hy = 0, hz = side, ih = 0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        const double tan2 = -m * m * std::log(rng.uniform());
        const double ct = 1.0 / std::sqrt(1.0 + tan2), st = std::sqrt(1.0 - ct * ct);
        const double phi = 2.0 * kPi * rng.uniform();
        hx = st * std::cos(phi), hy = st * std::sin(phi), hz = ct * side;
        ih = ix * hx + iy * hy + iz * hz;
        if (ih > 0.0) break;
    }
    if (ih <= 0.0) {
        w = 0.0;
        return false;
    }
    const double in = std::abs(iz), hn = std::abs(hz);
    const double eta = n2 / n1;
    const double F = fresnel_dielectric(ih, eta);
    double ox, oy, oz;
    bool transmitted;
    if (rng.uniform() <= F) {
        ox = 2.0 * ih * hx - ix, oy = 2.0 * ih * hy - iy, oz = 2.0 * ih * hz - iz;
        transmitted = false;
        if (oz * side <= 0.0) {
            w = 0.0;
            return false;
        }
    } else {
        const double e = 1.0 / eta;  // n1 / n2
        const double ct2 = 1.0 - e * e * (1.0 - ih * ih);
        if (ct2 <= 0.0) {  // cannot happen with F < 1, kept for safety
            w = 0.0;
            return false;
        }
        const double k = e * ih - std::sqrt(ct2);
        ox = k * hx - e * ix, oy = k * hy - e * iy, oz = k * hz - e * iz;
        transmitted = true;
        if (oz * side >= 0.0) {
            w = 0.0;
            return false;
        }
    }
    const double len = std::sqrt(ox * ox + oy * oy + oz * oz);
    ox /= len, oy /= len, oz /= len;
    const double on = std::abs(oz), oh = std::abs(ox * hx + oy * hy + oz * hz);
    const double G = std::min({1.0, 2.0 * hn * on / oh, 2.0 * hn * in / ih});
    w *= ih * G / (in * hn);
    ux = ox, uy = oy, uz = oz;
    return transmitted;
}

double henyey_greenstein_cosine(double g, PhotonRng& rng) {
    const double xi = rng.uniform();
    if (g == 0.0) return 2.0 * xi - 1.0;
    const double t = (1.0 - g * g) / (1.0 - g + 2.0 * g * xi);
    return std::clamp((1.0 + g * g - t * t) / (2.0 * g), -1.0, 1.0);
}

class Tracer {
public:
    Tracer(const McSetup& s) : s_(s) {
        z_top_.push_back(0.0);
        for (const McLayer& l : s.layers) z_top_.push_back(z_top_.back() + l.thickness);
    }

    void trace_one(PhotonRng& rng, Tally& t) const {
        double x = 0, y = 0, z = 0, ux = 0, uy = 0, uz = 1;
        double w = 1.0 - specular();
        if (s_.top_roughness > 0.0) {
            w = 1.0;
            if (!rough_top(s_.n_above, s_.layers[0].n, ux, uy, uz, w, rng)) {
                t.specular += w;  // reflected by the surface (or lost in it, w = 0)
                return;
            }
        }
        size_t layer = 0;
        bool scattered = false, alive = true;
        double step_left = 0.0;  // dimensionless (optical) step still to go
        while (alive) {
            const McLayer& L = s_.layers[layer];
            const double mut = L.sigma_a + L.sigma_s;
            if (step_left == 0.0) step_left = -std::log(rng.uniform());
            const double step = mut > 0.0 ? step_left / mut : std::numeric_limits<double>::infinity();
            double to_boundary = std::numeric_limits<double>::infinity();
            if (uz > 0.0) to_boundary = (z_top_[layer + 1] - z) / uz;
            else if (uz < 0.0) to_boundary = (z_top_[layer] - z) / uz;

            if (step > to_boundary) {
                x += to_boundary * ux;
                y += to_boundary * uy;
                z = uz > 0.0 ? z_top_[layer + 1] : z_top_[layer];
                if (mut > 0.0) step_left -= to_boundary * mut;
                cross(rng, t, x, y, ux, uy, uz, w, layer, scattered, alive, w);
            } else {
                x += step * ux;
                y += step * uy;
                z += step * uz;
                step_left = 0.0;
                const double dw = w * L.sigma_a / mut;
                w -= dw;
                t.absorbed += dw;
                scatter(L.g, rng, ux, uy, uz);
                scattered = true;
            }
            if (alive && w < kRouletteWeight) {
                if (rng.uniform() <= kRouletteChance) w /= kRouletteChance;
                else alive = false;
            }
        }
    }

    // The smooth top surface's normal-incidence reflection, taken out of the
    // launch weight; a rough top samples it instead.
    double specular() const {
        if (s_.top_roughness > 0.0) return 0.0;
        const double r = (s_.n_above - s_.layers[0].n) / (s_.n_above + s_.layers[0].n);
        return r * r;
    }

private:
    // The rough top surface, either way (McSetup::top_multiple_scattering):
    // true when the photon crossed it; w = 0 when it was lost.
    bool rough_top(double n1, double n2, double& ux, double& uy, double& uz, double& w, PhotonRng& rng) const {
        if (!s_.top_multiple_scattering) return rough_interface(s_.top_roughness, n1, n2, ux, uy, uz, w, rng);
        const InterfaceOutcome o = microsurface_walk(s_.top_roughness, n1, n2, ux, uy, uz, rng);
        if (o == InterfaceOutcome::Lost) w = 0.0;
        return o == InterfaceOutcome::Transmitted;
    }

    // The radial bin of an exit point at (x, y), or one past the last bin
    // when it lies beyond them. The quotient is compared before it is
    // converted: radius / bin_width can exceed any int (profile --model mc
    // --r-max 1e-9, bins of 4e-12 mm: a photon 0.01 mm out made int() of
    // 2.6e9, undefined, and the tally was written far outside its table).
    size_t bin_of(double x, double y) const {
        const double b = std::sqrt(x * x + y * y) / s_.bin_width;
        return b < double(s_.bins) ? size_t(b) : size_t(s_.bins);
    }

    void cross(PhotonRng& rng, Tally& t, double x, double y, double& ux, double& uy, double& uz, double w,
               size_t& layer, bool scattered, bool& alive, double& w_out) const {
        const bool up = uz < 0.0;
        const double n1 = s_.layers[layer].n;
        const bool leaves = up ? layer == 0 : layer + 1 == s_.layers.size();
        const double n2 = leaves ? (up ? s_.n_above : s_.n_below) : s_.layers[up ? layer - 1 : layer + 1].n;
        if (up && leaves && s_.top_roughness > 0.0) {
            double wr = w;
            if (rough_top(n1, n2, ux, uy, uz, wr, rng)) {
                const size_t bin = bin_of(x, y);
                t.R += wr;
                if (bin < t.R_bins.size()) t.R_bins[bin] += wr;
                alive = false;
            } else if (wr == 0.0) {
                alive = false;  // lost in the facet model
            } else {
                w_out = wr;  // reflected back inside, weight changed
            }
            return;
        }
        double ca2 = 0.0;
        const double r = fresnel(n1, n2, std::abs(uz), ca2);
        if (rng.uniform() <= r) {  // reflected
            uz = -uz;
            return;
        }
        if (leaves) {
            const size_t bin = bin_of(x, y);
            if (up) {
                t.R += w;
                if (bin < t.R_bins.size()) t.R_bins[bin] += w;
            } else if (!scattered) {
                t.T_direct += w;
            } else {
                t.T += w;
                if (bin < t.T_bins.size()) t.T_bins[bin] += w;
            }
            alive = false;
            return;
        }
        ux *= n1 / n2;
        uy *= n1 / n2;
        uz = up ? -ca2 : ca2;
        layer = up ? layer - 1 : layer + 1;
    }

    static void scatter(double g, PhotonRng& rng, double& ux, double& uy, double& uz) {
        const double cost = henyey_greenstein_cosine(g, rng);
        const double sint = std::sqrt(1.0 - cost * cost);
        const double psi = 2.0 * kPi * rng.uniform();
        const double cosp = std::cos(psi), sinp = std::sin(psi);
        if (std::abs(uz) > kCosZero) {
            ux = sint * cosp;
            uy = sint * sinp;
            uz = uz >= 0.0 ? cost : -cost;
        } else {
            const double temp = std::sqrt(1.0 - uz * uz);
            const double nx = sint * (ux * uz * cosp - uy * sinp) / temp + ux * cost;
            const double ny = sint * (uy * uz * cosp + ux * sinp) / temp + uy * cost;
            const double nz = -sint * cosp * temp + uz * cost;
            ux = nx;
            uy = ny;
            uz = nz;
        }
    }

    const McSetup& s_;
    std::vector<double> z_top_;  // depth of each layer's top, then the bottom of the last
};

}  // namespace

McResult trace_photons(const McSetup& setup) {
    const Tracer tracer(setup);
    // Chunks depend on the photon count and the bins only: at least 4096
    // photons, at most 1024 chunks plus one. Each chunk has its own random
    // stream and tally; tallies are added into the sums strictly in chunk
    // order, so the result does not depend on the thread count, and a
    // finished chunk is kept only until the chunks before it are in
    // (memory: a few tallies, not one per chunk, whatever the number of
    // bins). A chunk also holds at least as many photons as there are bins:
    // each tally is two tables of `bins`, zeroed and added once, so with a
    // fine table (profile --samples 1000000) 4096-photon chunks cost far more
    // in tallies than in photons (17 s for 2e6 photons on two threads, and
    // 7.6 GB at --threads 256); so the tallies cost no more than the photons
    // do, and the tallies alive at once stay within 2 chunks' worth each,
    // about 32 bytes a photon. (Every caller but `profile --samples` above
    // 4096 has fewer bins than 4096: their chunks are as they were.)
    const uint64_t chunk = std::max({uint64_t(4096), setup.photons / 1024, uint64_t(std::max(0, setup.bins))});
    const uint64_t chunks = (setup.photons + chunk - 1) / chunk;
    Tally sum;
    sum.R_bins.assign(size_t(setup.bins), 0.0);
    sum.T_bins.assign(size_t(setup.bins), 0.0);
    double R2 = 0.0, T2 = 0.0;  // per-photon second moments, for the standard errors
    std::map<uint64_t, std::pair<Tally, std::pair<double, double>>> waiting;
    uint64_t next_to_add = 0;
    std::mutex merge;
    std::condition_variable merged;
    bool aborted = false;  // a chunk failed: nothing more is added
    const size_t kMaxWaiting = 2 * size_t(std::max(1, setup.threads)) + 2;
    std::atomic<uint64_t> next{0}, done{0};
    auto run_chunk = [&](uint64_t c) {
        Tally t;
        t.R_bins.assign(size_t(setup.bins), 0.0);
        t.T_bins.assign(size_t(setup.bins), 0.0);
        PhotonRng rng(setup.seed, c);
        const uint64_t n = std::min(chunk, setup.photons - c * chunk);
        double r2 = 0.0, t2 = 0.0;
        for (uint64_t p = 0; p < n; ++p) {
            const double r0 = t.R, t0 = t.T;
            tracer.trace_one(rng, t);
            r2 += (t.R - r0) * (t.R - r0);
            t2 += (t.T - t0) * (t.T - t0);
        }
        std::unique_lock<std::mutex> lock(merge);
        // Memory stays bounded: a chunk finished far ahead of the next one
        // to add waits (that one itself never waits, so the run moves on).
        merged.wait(lock, [&] { return c == next_to_add || waiting.size() < kMaxWaiting || aborted; });
        if (aborted) return;
        waiting.emplace(c, std::make_pair(std::move(t), std::make_pair(r2, t2)));
        for (auto it = waiting.find(next_to_add); it != waiting.end(); it = waiting.find(next_to_add)) {
            const Tally& in = it->second.first;
            sum.R += in.R;
            sum.T += in.T;
            sum.T_direct += in.T_direct;
            sum.absorbed += in.absorbed;
            sum.specular += in.specular;
            for (int b = 0; b < setup.bins; ++b) {
                sum.R_bins[size_t(b)] += in.R_bins[size_t(b)];
                sum.T_bins[size_t(b)] += in.T_bins[size_t(b)];
            }
            R2 += it->second.second.first;
            T2 += it->second.second.second;
            waiting.erase(it);
            ++next_to_add;
        }
        lock.unlock();
        merged.notify_all();
        done.fetch_add(1);
    };
    // An exception in a worker (std::bad_alloc for a huge tally) stops the
    // hand-out of chunks and is rethrown here, not std::terminate.
    std::exception_ptr failure;
    std::mutex failure_lock;
    auto guarded = [&](uint64_t c) {
        try {
            run_chunk(c);
        } catch (...) {
            {
                std::lock_guard<std::mutex> lock(failure_lock);
                if (!failure) failure = std::current_exception();
            }
            next.store(chunks);
            {
                std::lock_guard<std::mutex> lock(merge);
                aborted = true;
            }
            merged.notify_all();
        }
    };
    auto work = [&] {
        for (uint64_t c; (c = next.fetch_add(1)) < chunks;) guarded(c);
    };
    // No more threads than chunks (the others would find no work). A thread
    // the system will not start (std::system_error: --threads 256 under a
    // ulimit) leaves the work to those that did start, with the same result;
    // it used to end the process in std::terminate with threads unjoined.
    std::vector<std::thread> threads;
    const uint64_t workers = std::min<uint64_t>(uint64_t(std::max(1, setup.threads)), chunks);
    for (uint64_t i = 1; i < workers; ++i) {
        try {
            threads.emplace_back(work);
        } catch (const std::system_error&) {
            break;
        }
    }
    // The calling thread works too, and reports progress between its chunks.
    auto last = std::chrono::steady_clock::now();
    for (uint64_t c; (c = next.fetch_add(1)) < chunks;) {
        guarded(c);
        const auto now = std::chrono::steady_clock::now();
        if (setup.progress && now - last > std::chrono::seconds(1)) {
            setup.progress(double(done.load()) / double(chunks));
            last = now;
        }
    }
    for (auto& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);

    McResult r;
    const double total = double(setup.photons);
    r.specular = tracer.specular() + sum.specular / total;
    r.R = sum.R / total;
    r.T = sum.T / total;
    r.T_direct = sum.T_direct / total;
    r.absorbed = sum.absorbed / total;
    // Each photon leaves through the top or the bottom once (all-or-none
    // Fresnel), so its score is one draw: the standard error of the mean.
    auto stderr_of = [&](double m2, double mean) {
        return total > 1.0 ? std::sqrt(std::max(m2 / total - mean * mean, 0.0) / (total - 1.0)) : 0.0;
    };
    r.R_stderr = stderr_of(R2, r.R);
    r.T_stderr = stderr_of(T2, r.T);
    r.R_profile = std::move(sum.R_bins);
    r.T_profile = std::move(sum.T_bins);
    const double dr = setup.bin_width;
    for (int b = 0; b < setup.bins; ++b) {
        const double i = b + 0.5;
        r.bin_centres.push_back((i + 1.0 / (12.0 * i)) * dr);
        const double area = 2.0 * kPi * i * dr * dr;  // annulus b
        r.R_profile[size_t(b)] /= total * area;
        r.T_profile[size_t(b)] /= total * area;
    }
    return r;
}

}  // namespace st::optics
