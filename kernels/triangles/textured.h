// textured.h: twin of glsl/textured.vert and glsl/textured.frag.
#pragma once

#include "shading/program.h"

namespace st {

class TexturedVertex final : public VertexTwin {
public:
    int varying_count() const override { return 2; }
    void run(const glm::vec4* attributes, VertexOut& out) const override;
};

class TexturedFragment final : public FragmentProgram<TexturedFragment> {
public:
    void bind(const Bindings& b) override { tex_ = &b.sampler("tex"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;  // uniform sampler2D tex
};

}  // namespace st
