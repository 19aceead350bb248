// coverage_frag.cpp: twin of glsl/coverage.frag, line for line.
#include "kernels/harness/coverage.h"

namespace st {

Vec4 CoverageFragment::main(const Fragment&) const {
    return Vec4(1.0f);
}

}  // namespace st
