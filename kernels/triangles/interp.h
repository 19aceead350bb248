// interp.h: twin of glsl/interp.vert and glsl/interp.frag.
#pragma once

#include "shading/program.h"

namespace st {

class InterpVertex final : public VertexTwin {
public:
    int varying_count() const override { return 1; }
    void run(const glm::vec4* attributes, VertexOut& out) const override;
};

class InterpFragment final : public FragmentProgram<InterpFragment> {
public:
    Vec4 main(const Fragment& frag) const;
};

}  // namespace st
