// relief_exact.h: the relief sweep's yardstick as a twin (CPU only): the
// relief-mapping program with its search replaced by the exact first
// crossing (reference/relief_intersection.h), so that the image shaded at
// the exact hit comes from the same shading code as every setting's. Kept
// out of kernels/ so that the twins do not depend on the reference.
#pragma once

#include <memory>
#include <string>

#include "shading/twin_library.h"

namespace st {

// The built-in twins plus kExactReliefMapping, the relief_mapping program
// with the exact intersection.
class ReliefSweepTwins final : public TwinLibrary {
public:
    static constexpr const char* kExactReliefMapping = "relief_mapping_exact";

    std::unique_ptr<VertexTwin> make_vertex(const std::string& name) const override;
    std::unique_ptr<FragmentTwin> make_fragment(const std::string& name) const override;
    std::vector<std::string> vertex_names() const override;
    std::vector<std::string> fragment_names() const override;
};

}  // namespace st
