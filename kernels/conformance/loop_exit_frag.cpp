// loop_exit_frag.cpp: twin of glsl/conformance/loop_exit.frag, line for line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void LoopExitFragment::bind(const Bindings& b) {
    tex_ = &b.sampler("tex");
    steps_ = b.get_int("steps");
    dir_ = b.get_vec2("dir");
    threshold_ = b.get_float("threshold");
}

uint32_t LoopExitFragment::inputs_read() const { return reads(v_colour, "y") | reads(v_uv, "xy"); }

Vec4 LoopExitFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec2 uv = frag.varying(v_uv).xy();
    Float t = 0.0f;
    Vec4 hit(0.0f);
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < Int(steps_)));
        const Vec4 c = tex_->sample(uv + Vec2(dir_) * t);
        exec.if_(c.w * frag.varying(v_colour).y > Float(threshold_), [&] {
            exec.assign(hit, c);
            loop.break_();
        });
        exec.assign(t, t + 1.0f);
        exec.assign(i, i + 1);
    });
    return Vec4(hit.xyz(), t / Float(float(steps_)));
}

}  // namespace st
