// relief_exact.cpp: see relief_exact.h.
#include "app/quality/relief_exact.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <utility>
#include <vector>

#include "kernels/relief/relief.h"
#include "reference/relief_intersection.h"
#include "reference/relief_sampled_crossing.h"
#include "texture/sampler2d.h"

namespace st {

namespace {

// Per lane, the exact crossing on the levels and weight that the search's
// textureGrad reads blend (the same LevelChoice), so that what differs is
// the search's error (and, on the bilinear surface, the 8-bit filter's
// rounding of the surface). Inactive lanes and lanes with a non-finite ray
// (helper lanes outside the triangle) keep s = 1 and no hit, as does a ray
// too long to trace (reference::RayTooLong: a view along the surface).
// Anything else a lane meets runs on a worker thread, where it cannot be
// thrown: the lane keeps no hit and the error goes to `errors`, which the
// caller checks after the render (ReliefSweepTwins::take_error).
class ExactReliefIntersector final : public ReliefIntersector {
public:
    enum class Surface { Bilinear, Sampled };
    ExactReliefIntersector(Surface surface, std::shared_ptr<ReliefSweepTwins::Errors> errors)
        : surface_(surface), errors_(std::move(errors)) {}

    // The renderer makes a twin (and so an intersector) per prepared draw and
    // binds it before any fragment: the fields are built here, one for each
    // map bound (a map is known by its texture and its texels).
    void bind(const Sampler2D& map) override {
        for (const Field& f : fields_)
            if (f.texture == &map.texture() && f.texels == map.texture().texels8.data()) return;
        fields_.push_back({&map.texture(), map.texture().texels8.data(),
                           std::make_unique<reference::ReliefHeightField>(map.texture())});
    }
    Float first_crossing(const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh, Float side,
                         const Vec2& dx, const Vec2& dy, Mask leaving, Mask active, Mask& hit) const override {
        const reference::ReliefHeightField* bound = nullptr;
        try {
            bound = &field_of(map);
        } catch (const std::exception& e) {
            errors_->note(e.what());
            hit = Mask(false);
            return Float(1.0f);
        }
        const reference::ReliefHeightField& field = *bound;
        const texel::LevelChoice c = map.grad_levels(dx, dy);
        const bool mipped = !map.texture().mips.empty();  // else c is unused: level 0
        Float t(1.0f);
        Int hits(0);
        for (int lane = 0; lane < kLanes; ++lane) {
            reference::SearchRay ray;
            ray.u0 = uv.x[lane], ray.v0 = uv.y[lane], ray.du = offset.x[lane], ray.dv = offset.y[lane];
            ray.a = a[lane], ray.dh = dh[lane], ray.side = side[lane] < 0 ? -1.0 : 1.0, ray.leaving = leaving[lane];
            if (!active[lane] || !std::isfinite(ray.u0 + ray.v0 + ray.du + ray.dv + ray.a + ray.dh)) continue;
            const int l0 = mipped ? c.level0[lane] : 0;
            const int l1 = c.two_levels ? c.level1[lane] : l0;
            try {
                if (surface_ == Surface::Bilinear) {
                    if (ray.a != 1 || ray.dh != -1 || ray.side != 1 || ray.leaving)
                        throw std::logic_error("the bilinear crossing answers view rays from the top only");
                    const double f = c.two_levels ? std::clamp(double(c.fpart[lane]), 0.0, 1.0) : 0.0;
                    t.set(lane, float(field.first_crossing(l0, l1, f, ray.u0, ray.v0, ray.du, ray.dv).t));
                    hits.set(lane, -1);
                } else {
                    const reference::SampledCrossing x = sampled_crossing(field, map, lane_levels(c, lane), l0, l1, ray);
                    t.set(lane, float(x.t));
                    hits.set(lane, x.hit ? -1 : 0);
                }
            } catch (const reference::RayTooLong&) {
                // no crossing (above)
            } catch (const std::exception& e) {
                errors_->note(e.what());
            }
        }
        hit = hits != Int(0);
        return t;
    }

private:
    struct Field {
        const Texture* texture;
        const uint8_t* texels;
        std::unique_ptr<reference::ReliefHeightField> field;
    };
    Surface surface_;
    std::shared_ptr<ReliefSweepTwins::Errors> errors_;
    std::vector<Field> fields_;

    const reference::ReliefHeightField& field_of(const Sampler2D& map) const {
        for (const Field& f : fields_)
            if (f.texture == &map.texture() && f.texels == map.texture().texels8.data()) return *f.field;
        throw std::logic_error("ExactReliefIntersector: a map that was not bound");
    }

    // Lane `lane` of `c` in every lane: the reads along one pixel's ray.
    static texel::LevelChoice lane_levels(const texel::LevelChoice& c, int lane) {
        texel::LevelChoice one;
        one.level0 = Int(c.level0[lane]);
        one.level1 = Int(c.level1[lane]);
        one.fpart = Float(c.fpart[lane]);
        one.minified = Mask(c.minified[lane]);
        one.two_levels = c.two_levels;
        return one;
    }

    static reference::SampledCrossing sampled_crossing(const reference::ReliefHeightField& field, const Sampler2D& map,
                                                       const texel::LevelChoice& levels, int l0, int l1,
                                                       const reference::SearchRay& ray) {
        const auto read = [&](const double* u, const double* v, int n, float* h) {
            Vec2 p;
            for (int i = 0; i < kLanes; ++i) {
                p.x.set(i, float(u[std::min(i, n - 1)]));
                p.y.set(i, float(v[std::min(i, n - 1)]));
            }
            const Float heights = map.sample_grad_alpha(p, levels);
            for (int i = 0; i < n; ++i) h[i] = heights[i];
        };
        const std::vector<int> blended = l0 == l1 ? std::vector<int>{l0} : std::vector<int>{l0, l1};
        return reference::first_sampled_crossing(field, blended, ray, read, kLanes);
    }
};

}  // namespace

void ReliefSweepTwins::Errors::note(const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (first_.empty()) first_ = what;
}

std::string ReliefSweepTwins::Errors::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(first_, std::string());
}

ReliefSweepTwins::ReliefSweepTwins() : ReliefSweepTwins(std::make_shared<Errors>()) {}

ReliefSweepTwins::ReliefSweepTwins(std::shared_ptr<Errors> errors)
    : TwinsWithFragment({{kExactReliefMapping,
                          [errors] {
                              return std::make_unique<ReliefMappingFragment>(std::make_shared<ExactReliefIntersector>(
                                  ExactReliefIntersector::Surface::Bilinear, errors));
                          }},
                         {kSampledReliefMapping,
                          [errors] {
                              return std::make_unique<ReliefMappingFragment>(std::make_shared<ExactReliefIntersector>(
                                  ExactReliefIntersector::Surface::Sampled, errors));
                          }},
                         {kSampledTwoLayer,
                          [errors] {
                              return std::make_unique<TwoLayerFragment>(std::make_shared<ExactReliefIntersector>(
                                  ExactReliefIntersector::Surface::Sampled, errors));
                          }}}),
      errors_(std::move(errors)) {}

std::string ReliefSweepTwins::take_error() const { return errors_->take(); }

}  // namespace st
