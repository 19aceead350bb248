// relief_exact.h: the relief yardsticks as twins (CPU only): the
// relief programs with their searches replaced by exact first
// crossings, so that the image shaded at that hit comes from the same
// shading code as every setting's. Kept out of kernels/ so that the twins
// do not depend on the reference.
//
// Two crossings, two questions:
// - kSampledReliefMapping, the crossing of the surface the sampler returns
//   (reference/relief_sampled_crossing.h): what every search converges to,
//   so a setting's error against it is the search's own. `quality: auto`
//   chooses against this one.
// - kExactReliefMapping, the crossing of the bilinear surface in exact
//   arithmetic (reference/relief_intersection.h): adds the error of the
//   8-bit filter, which no search setting changes (the floor the sweep and
//   auto's record show).
// - kSampledTwoLayer, the two-layer program (two_layer.frag: the occlusion
//   and absorption rows too) with every search, of the view, refracted,
//   reflected and light rays, replaced by the sampled surface's crossing.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "app/quality/twins_with_fragment.h"

namespace st {

class ReliefSweepTwins final : public TwinsWithFragment {
public:
    static constexpr const char* kExactReliefMapping = "relief_mapping_exact";
    static constexpr const char* kSampledReliefMapping = "relief_mapping_sampled_exact";
    static constexpr const char* kSampledTwoLayer = "two_layer_sampled_exact";

    ReliefSweepTwins();

    // The first error an exact crossing met since the last call, or empty.
    // They run on the renderer's worker threads, which cannot throw: the
    // lane keeps no crossing, and whoever rendered an exact frame calls this
    // after it and throws what it returns.
    std::string take_error() const;

    class Errors {
    public:
        void note(const std::string& what);
        std::string take();

    private:
        std::mutex mutex_;
        std::string first_;
    };

private:
    explicit ReliefSweepTwins(std::shared_ptr<Errors> errors);
    std::shared_ptr<Errors> errors_;
};

}  // namespace st
