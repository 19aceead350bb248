// profile_exact.cpp: the exact image of a flat profile slab (profile_exact.h).
#include "app/profile_exact.h"

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat4x4.hpp>

#include "optics/diffuse_fresnel.h"
#include "optics/rough_surface.h"
#include "reference/profile_convolution.h"
#include "scene/input_error.h"
#include "scene/profile_scene.h"
#include "scene/scene_spaces.h"

namespace st {

namespace {

// f(x) on [lo, hi] at n + 1 points, read linearly; constant beyond.
class Tabulated {
public:
    Tabulated(const std::function<double(double)>& f, double lo, double hi, int n) : lo_(lo), h_((hi - lo) / n) {
        for (int i = 0; i <= n; ++i) v_.push_back(f(lo + h_ * i));
        // The midpoints against f itself: the table's own error.
        for (int i = 0; i < n; ++i) error_ = std::max(error_, std::abs(f(lo + h_ * (i + 0.5)) - (*this)(lo + h_ * (i + 0.5))));
    }
    double operator()(double x) const {
        const double u = (x - lo_) / h_;
        if (!(u > 0)) return v_.front();
        if (!(u < double(v_.size() - 1))) return v_.back();
        const size_t i = size_t(u);
        const double w = u - double(i);
        return v_[i] + w * (v_[i + 1] - v_[i]);
    }
    double error() const { return error_; }

private:
    double lo_, h_;
    std::vector<double> v_;
    double error_ = 0;
};

}  // namespace

ProfileExact exact_profile_image(const Scene& scene) {
    if (scene.kind != "profile") throw InputError("scene '" + scene.name + "' is not a profile scene");
    JsonReader r(scene.document, "");
    r.bind(profile_space());
    const ProfileSceneSpec spec = read_profile_scene(r);
    if (spec.shape.kind != "slab") throw InputError("the exact image needs the flat slab (geometry.shape \"slab\")");
    const int width = scene.frame.passes.back().width, height = scene.frame.passes.back().height;
    const auto profiles = build_profiles(spec.material, spec.gather);
    const double reach = profiles->r_max;
    const bool spot = spec.spot.z > 0, edge = spec.edge.w > 0;
    const glm::dvec2 centre(spec.spot.x, spec.spot.y), normal(spec.edge.x, spec.edge.y);
    const double radius = spec.spot.z, offset = spec.edge.z;
    if (spot && edge && glm::dot(centre, normal) - offset + radius > 0)
        throw InputError("the exact image needs the spot wholly on the shadowed side of the edge");

    // The light entering each face: cos theta times the boundary's
    // transmittance, as irradiance.frag computes it.
    const glm::dvec3 l = glm::normalize(glm::dvec3(spec.light_direction));
    const double eta = spec.material.eta();
    auto entering = [&](double c) {
        if (!(c > 0)) return 0.0;
        if (spec.material.roughness() > 0) return c * optics::RoughSurface(spec.material.roughness(), eta).rho_dt(c);
        return c * (1.0 - optics::fresnel_dielectric(c, eta));
    };
    const double front = entering(l.z), back = spec.material.thin() ? entering(-l.z) : 0.0;

    // The whole profile, tail included: the ground truth is not cut where
    // the gather's reach ends. A tabulated profile (layered, Monte Carlo)
    // is read linearly between its radii, so the integrals break there.
    const reference::ConvolutionSettings settings{4.0 * reach, 1e-10, profiles->knots};
    const int n = 4000;
    ProfileExact out;
    out.reach_mm = reach;
    std::vector<Tabulated> half_R, half_T, disk_R, disk_T;
    std::array<double, 3> total_R{}, total_T{};
    for (int c = 0; c < 3; ++c) {
        const auto R = profiles->R[size_t(c)], T = profiles->T[size_t(c)];
        total_R[size_t(c)] = reference::profile_total(R, settings);
        total_T[size_t(c)] = spec.material.thin() ? reference::profile_total(T, settings) : 0.0;
        auto tables = [&](const reference::RadialProfile& P, std::vector<Tabulated>& half, std::vector<Tabulated>& disk,
                          double total) {
            if (edge) {
                half.emplace_back([&](double d) { return reference::convolve_half_plane(P, d, settings); },
                                  -settings.r_max, settings.r_max, n);
                out.table_error = std::max(out.table_error, half.back().error() / total);
            }
            if (spot) {
                disk.emplace_back([&](double rho) { return reference::convolve_disk(P, radius, rho, settings); }, 0.0,
                                  radius + settings.r_max, n);
                out.table_error = std::max(out.table_error, disk.back().error() / total);
            }
        };
        tables(R, half_R, disk_R, total_R[size_t(c)]);
        if (spec.material.thin()) tables(T, half_T, disk_T, total_T[size_t(c)]);
    }

    // The interior: where the slab's edge, had it been lit, would have
    // sent less than a thousandth of the profile's total (the exact
    // half-plane convolution at -margin), in every channel and profile.
    double margin = 0;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < (spec.material.thin() ? 2 : 1); ++k) {
            const auto P = k == 0 ? profiles->R[size_t(c)] : profiles->T[size_t(c)];
            const double total = k == 0 ? total_R[size_t(c)] : total_T[size_t(c)];
            double lo = 0, hi = settings.r_max;
            for (int i = 0; i < 40; ++i) {
                const double mid = 0.5 * (lo + hi);
                (reference::convolve_half_plane(P, -mid, settings) > 1e-3 * total ? lo : hi) = mid;
            }
            margin = std::max(margin, hi);
        }
    out.margin_mm = margin;

    // Each pixel centre's ray against the plane z = 0, from the frame's own
    // transform (rows top to bottom, as the images are).
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(profile_view_proj(spec, SceneSize{width, height})));
    out.image = Image(width, height);
    out.region.assign(size_t(width) * size_t(height), 0);
    const double half_size = 0.5 * spec.shape.size_mm;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0;
            const glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0), b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
            const glm::dvec3 p0 = glm::dvec3(a) / a.w, p1 = glm::dvec3(b) / b.w;
            float* px = out.image.pixel(x, y);
            const double t = p0.z / (p0.z - p1.z);
            const glm::dvec3 p = p0 + t * (p1 - p0);
            if (!(t > 0) || std::abs(p.x) > half_size || std::abs(p.y) > half_size) {
                px[0] = px[1] = px[2] = std::nanf("");
                px[3] = 1.0f;
                continue;
            }
            const bool inner = std::abs(p.x) <= half_size - margin && std::abs(p.y) <= half_size - margin;
            out.region[size_t(y) * size_t(width) + size_t(x)] = inner ? 1 : 2;
            const double d = glm::dot(glm::dvec2(p), normal) - offset, rho = glm::length(glm::dvec2(p) - centre);
            for (int c = 0; c < 3; ++c) {
                auto lit = [&](const std::vector<Tabulated>& half, const std::vector<Tabulated>& disk, double total) {
                    if (!spot && !edge) return total;
                    return (edge ? half[size_t(c)](d) : 0.0) + (spot ? disk[size_t(c)](rho) : 0.0);
                };
                double m = front * lit(half_R, disk_R, total_R[size_t(c)]);
                if (spec.material.thin()) m += back * lit(half_T, disk_T, total_T[size_t(c)]);
                px[c] = float(double(spec.irradiance[c]) * m / std::numbers::pi);
            }
            px[3] = 1.0f;
        }
    return out;
}

}  // namespace st
