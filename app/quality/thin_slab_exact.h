// thin_slab_exact.h: the thin-slab `quality: auto` yardstick as a twin (CPU
// only): the fragment variant's program (thin_slab.frag, Eq. 4-9 per
// fragment) with its arithmetic in double and without the shader's series
// approximations (std::expm1 where the GLSL has its Taylor branches), on
// the same interpolated position, normal and flag texel. What a variant
// differs from it by is then its own evaluation error: per vertex (vertex,
// host) or in float (fragment). Kept out of kernels/ (the twins mirror GLSL;
// this mirrors nothing), like relief_exact.h.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/quality/twins_with_fragment.h"

namespace st {

// The built-in twins plus kExactThinSlab.
class ThinSlabExactTwins final : public TwinsWithFragment {
public:
    static constexpr const char* kExactThinSlab = "thin_slab_exact";

    ThinSlabExactTwins();
};

}  // namespace st
