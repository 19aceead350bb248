// coverage_frag.cpp: twin of glsl/coverage.frag, line for line.
#include "kernels/harness/coverage.h"

namespace st {

glm::vec4 CoverageFragment::main(const Fragment&) const {
    return glm::vec4(1.0f);
}

}  // namespace st
