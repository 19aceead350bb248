// loop_budget_frag.cpp: twin of glsl/conformance/loop_budget.frag, line for
// line; the budget itself is Exec's (shading/control_flow.h).
#include "kernels/conformance/conformance.h"

#include "shading/glsl_math.h"

namespace st {

void LoopBudgetFragment::bind(const Bindings& b) {
    long_steps_ = b.get_int("long_steps");
    short_steps_ = b.get_int("short_steps");
    slow_a_ = b.get_vec2("slow_a");
    slow_b_ = b.get_vec2("slow_b");
}

Vec4 LoopBudgetFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec2 p(glsl::floor(frag.frag_coord().x), glsl::floor(frag.frag_coord().y));
    const Mask slow = (p.x == Float(slow_a_.x) && p.y == Float(slow_a_.y)) ||
                      (p.x == Float(slow_b_.x) && p.y == Float(slow_b_.y));
    const Int n = select(slow, Int(long_steps_), Int(short_steps_));
    Float a = 0.0f;
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < n));
        exec.assign(a, a + 1.0f);
        exec.assign(i, i + 1);
    });
    Float b = 0.0f;
    Int j = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(j < Int(short_steps_)));
        exec.assign(b, b + 1.0f);
        exec.assign(j, j + 1);
    });
    return Vec4(a / 65536.0f, b / Float(float(short_steps_)), 0.25f, 1.0f);
}

}  // namespace st
