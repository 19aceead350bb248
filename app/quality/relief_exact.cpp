// relief_exact.cpp: see relief_exact.h.
#include "app/quality/relief_exact.h"

#include <algorithm>
#include <cmath>

#include "kernels/relief/relief.h"
#include "reference/relief_intersection.h"
#include "texture/sampler2d.h"

namespace st {

namespace {

// Per lane, the exact crossing on the levels and weight that the search's
// textureGrad reads blend (the same LevelChoice), so that what differs is
// the search's error, plus the 8-bit filter's rounding of the surface.
// Lanes with a non-finite ray (helper lanes outside the triangle) keep 1.
class ExactReliefIntersector final : public ReliefIntersector {
public:
    // The renderer makes a twin (and so an intersector) per prepared draw and
    // binds it once: the field is built here, for the texture just bound.
    void bind(const Sampler2D& map) override { field_ = std::make_unique<reference::ReliefHeightField>(map.texture()); }
    Float first_crossing(const Sampler2D& map, const Vec2& uv, const Vec2& offset, const Vec2& dx,
                         const Vec2& dy) const override {
        const texel::LevelChoice c = map.grad_levels(dx, dy);
        const bool mipped = !map.texture().mips.empty();  // else c is unused: level 0
        Float t(1.0f);
        for (int lane = 0; lane < kLanes; ++lane) {
            const double in[4] = {uv.x[lane], uv.y[lane], offset.x[lane], offset.y[lane]};
            if (!std::isfinite(in[0] + in[1] + in[2] + in[3])) continue;
            const double f = c.two_levels ? std::clamp(double(c.fpart[lane]), 0.0, 1.0) : 0.0;
            const int l0 = mipped ? c.level0[lane] : 0;
            const int l1 = c.two_levels ? c.level1[lane] : l0;
            t.set(lane, float(field_->first_crossing(l0, l1, f, in[0], in[1], in[2], in[3]).t));
        }
        return t;
    }

private:
    std::unique_ptr<reference::ReliefHeightField> field_;
};

}  // namespace

ReliefSweepTwins::ReliefSweepTwins()
    : TwinsWithFragment(kExactReliefMapping, [] {
          return std::make_unique<ReliefMappingFragment>(std::make_shared<ExactReliefIntersector>());
      }) {}

}  // namespace st
