// relief_exact.cpp: see relief_exact.h.
#include "app/quality/relief_exact.h"

#include <algorithm>
#include <cmath>
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
// too long to trace (over 1e7 texel edges, or 2e6 steps of the staircase
// read: a view along the surface), which the reference throws for.
class ExactReliefIntersector final : public ReliefIntersector {
public:
    enum class Surface { Bilinear, Sampled };
    explicit ExactReliefIntersector(Surface surface) : surface_(surface) {}

    // The renderer makes a twin (and so an intersector) per prepared draw and
    // binds it once: the fields are built here, one for each map bound.
    void bind(const Sampler2D& map) override {
        for (const auto& f : fields_)
            if (f.first == &map.texture()) return;
        fields_.emplace_back(&map.texture(), std::make_unique<reference::ReliefHeightField>(map.texture()));
    }
    Float first_crossing(const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh, Float side,
                         const Vec2& dx, const Vec2& dy, Mask leaving, Mask active, Mask& hit) const override {
        const reference::ReliefHeightField& field = field_of(map);
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
            } catch (const std::invalid_argument&) {
                // too long a ray (above): no crossing
            }
        }
        hit = hits != Int(0);
        return t;
    }

private:
    Surface surface_;
    std::vector<std::pair<const Texture*, std::unique_ptr<reference::ReliefHeightField>>> fields_;

    const reference::ReliefHeightField& field_of(const Sampler2D& map) const {
        for (const auto& f : fields_)
            if (f.first == &map.texture()) return *f.second;
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

ReliefSweepTwins::ReliefSweepTwins()
    : TwinsWithFragment({{kExactReliefMapping,
                          [] {
                              return std::make_unique<ReliefMappingFragment>(std::make_shared<ExactReliefIntersector>(
                                  ExactReliefIntersector::Surface::Bilinear));
                          }},
                         {kSampledReliefMapping,
                          [] {
                              return std::make_unique<ReliefMappingFragment>(std::make_shared<ExactReliefIntersector>(
                                  ExactReliefIntersector::Surface::Sampled));
                          }},
                         {kSampledTwoLayer, [] {
                              return std::make_unique<TwoLayerFragment>(std::make_shared<ExactReliefIntersector>(
                                  ExactReliefIntersector::Surface::Sampled));
                          }}}) {}

}  // namespace st
