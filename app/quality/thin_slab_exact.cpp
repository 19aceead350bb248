// thin_slab_exact.cpp: see thin_slab_exact.h.
#include "app/quality/thin_slab_exact.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "reference/thin_slab_brackets.h"
#include "texture/sampler2d.h"

namespace st {

namespace {

constexpr double kInv4Pi = 0.25 / 3.14159265358979323846;

// Eq. 4-9 at one fragment, in double. The model's own guards stay (mu and
// mu0 at least MU_MIN, r2 at least R2_MIN: they define it at grazing
// angles); the series branches go, as double needs none: the brackets are
// the stable forms of reference/thin_slab_brackets.h.
glm::dvec4 thin_slab_exact(const glm::dvec3& p, const glm::dvec3& n_in, const glm::dvec3& eye,
                           const glm::dvec3& light, double power, double tau1, const glm::dvec3& albedo) {
    const glm::dvec3 n = glm::normalize(n_in);
    const glm::dvec3 to_light = light - p;
    const double r2 = std::max(glm::dot(to_light, to_light), double(R2_MIN));
    const glm::dvec3 l = to_light / std::sqrt(r2);
    const glm::dvec3 w = glm::normalize(eye - p);
    const double cos_l = glm::dot(n, l), cos_v = glm::dot(n, w);
    const double mu0 = std::max(std::abs(cos_l), double(MU_MIN)), mu = std::max(std::abs(cos_v), double(MU_MIN));
    const bool frontlit = (cos_l >= 0.0) == (cos_v >= 0.0);
    const double factor = frontlit ? reference::frontlit_bracket(tau1, mu, mu0) : reference::backlit_bracket(tau1, mu, mu0);
    const double radiance = power * kInv4Pi * mu0 / r2 * kInv4Pi * factor;
    return glm::dvec4(albedo * radiance, std::exp(-tau1 / mu));
}

// thin_slab.frag's inputs and uniforms, evaluated by thin_slab_exact per
// lane. Lanes with non-finite inputs (helper lanes far outside) give 0.
class ExactThinSlabFragment final : public FragmentProgram<ExactThinSlabFragment> {
public:
    void bind(const Bindings& b) override {
        u_.read(b, true);
        flag_ = &b.sampler("flag");
    }
    uint32_t inputs_read() const override { return reads(0, "xyz") | reads(1, "xyz") | reads(2, "xy"); }
    Vec4 main(const Fragment& frag) const {
        const Vec3 texel = flag_->sample(frag.varying(2).xy()).xyz();
        const Vec4 &p = frag.varying(0), &n = frag.varying(1);
        Vec4 out(Float(0.0f));
        for (int lane = 0; lane < kLanes; ++lane) {
            const glm::dvec3 pl(p.x[lane], p.y[lane], p.z[lane]), nl(n.x[lane], n.y[lane], n.z[lane]);
            if (!std::isfinite(pl.x + pl.y + pl.z + nl.x + nl.y + nl.z) || glm::dot(nl, nl) == 0.0) continue;
            const glm::dvec3 albedo = glm::dvec3(u_.albedo) * glm::dvec3(texel.x[lane], texel.y[lane], texel.z[lane]);
            const glm::dvec4 c = thin_slab_exact(pl, nl, glm::dvec3(u_.eye), glm::dvec3(u_.light), u_.power, u_.tau1, albedo);
            out.x.set(lane, float(c.x));
            out.y.set(lane, float(c.y));
            out.z.set(lane, float(c.z));
            out.w.set(lane, float(c.w));
        }
        return out;
    }

private:
    ThinSlabUniforms u_;
    const Sampler2D* flag_ = nullptr;
};

}  // namespace

ThinSlabExactTwins::ThinSlabExactTwins()
    : TwinsWithFragment(kExactThinSlab, [] { return std::make_unique<ExactThinSlabFragment>(); }) {}

}  // namespace st
