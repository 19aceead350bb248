// coverage.h: twin of glsl/coverage.frag.
#pragma once

#include "shading/program.h"

namespace st {

class CoverageFragment final : public FragmentProgram<CoverageFragment> {
public:
    Vec4 main(const Fragment&) const;
    uint32_t inputs_read() const override { return 0; }
};

}  // namespace st
