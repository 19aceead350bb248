// background.h: twin of glsl/background.vert and glsl/background.frag.
#pragma once

#include "shading/program.h"

namespace st {

class Sampler2D;

class BackgroundVertex final : public VertexTwin {
public:
    int varying_count() const override { return 1; }
    void run(const glm::vec4* attributes, VertexOut& out) const override;
};

class BackgroundFragment final : public FragmentProgram<BackgroundFragment> {
public:
    void bind(const Bindings& b) override { painting_ = &b.sampler("painting"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* painting_ = nullptr;
};

}  // namespace st
