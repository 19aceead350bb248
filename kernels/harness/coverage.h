// coverage.h: twin of glsl/coverage.frag.
#pragma once

#include "shading/program.h"

namespace st {

class CoverageFragment final : public ScalarFragmentTwin<CoverageFragment> {
public:
    glm::vec4 main(const Fragment&) const;
};

}  // namespace st
