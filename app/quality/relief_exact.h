// relief_exact.h: the relief sweep's yardstick as a twin (CPU only): the
// relief-mapping program with its search replaced by the exact first
// crossing (reference/relief_intersection.h), so that the image shaded at
// the exact hit comes from the same shading code as every setting's. Kept
// out of kernels/ so that the twins do not depend on the reference.
#pragma once

#include <memory>
#include <string>

#include "app/quality/twins_with_fragment.h"

namespace st {

// The built-in twins plus kExactReliefMapping, the relief_mapping program
// with the exact intersection.
class ReliefSweepTwins final : public TwinsWithFragment {
public:
    static constexpr const char* kExactReliefMapping = "relief_mapping_exact";

    ReliefSweepTwins();
};

}  // namespace st
