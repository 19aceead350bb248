// control_flow_test.cpp: Exec and Loop against what llvmpipe was measured
// to do (docs/llvmpipe/lanes-and-control-flow.md, appendix E1-E3, E5): the
// shared loop budget, per-group termination, frozen variables after break,
// continue, discard leaving loops, and both sides of an if.
#include "shading/control_flow.h"

#include <gtest/gtest.h>

namespace st {

namespace {

// for (int i = 0; i < n; ++i) for (int j = 0; j < m; ++j) c += 1.0;
Float nested_count(Exec& exec, Int n, Int m) {
    Float c = 0.0f;
    Int i = 0;
    exec.loop([&](Loop& outer) {
        outer.break_if(!(i < n));
        Int j = 0;
        exec.loop([&](Loop& inner) {
            inner.break_if(!(j < m));
            exec.assign(c, c + 1.0f);
            exec.assign(j, j + 1);
        });
        exec.assign(i, i + 1);
    });
    return c;
}

// for (int k = 0; k < n; ++k) d += 1.0;
Float count(Exec& exec, Int n) {
    Float d = 0.0f;
    Int k = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(k < n));
        exec.assign(d, d + 1.0f);
        exec.assign(k, k + 1);
    });
    return d;
}

}  // namespace

// E1: the budget of 65535 passes is shared by every loop of an invocation.
TEST(ControlFlow, NestedLoopsShareTheMeasuredBudget) {
    const struct { int n, m; float c; } cases[] = {
        {300, 300, 65101.0f}, {1, 70000, 65535.0f}, {4000, 33, 61791.0f}, {4000, 40, 62415.0f}, {10, 10, 100.0f}};
    for (const auto& k : cases) {
        Exec exec;
        const Float c = nested_count(exec, Int(k.n), Int(k.m));
        for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(c[lane], k.c) << k.n << " x " << k.m;
    }
}

// E2: lane 0 loops 10^6 times, which spends its group's budget; a later
// 100-pass loop then runs once in that group only.
TEST(ControlFlow, BudgetIsPerEightLaneGroup) {
    Exec exec;
    Int n = 10;
    n = select(Mask::from_bits(1), Int(1000000), n);
    const Float first = count(exec, n);
    const Float second = count(exec, Int(100));
    EXPECT_EQ(first[0], 65535.0f);
    for (int lane = 1; lane < kLanes; ++lane) EXPECT_EQ(first[lane], 10.0f);
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(second[lane], lane < 8 ? 1.0f : 100.0f) << lane;
}

// Each lane leaves at its own break and keeps the values it had then.
TEST(ControlFlow, BreakFreezesEachLane) {
    Exec exec;
    Int n = 0;
    for (int lane = 0; lane < kLanes; ++lane) n = select(Mask::from_bits(1u << lane), Int(lane * 3), n);
    const Float d = count(exec, n);
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(d[lane], float(lane * 3));
    EXPECT_TRUE(all(exec.active()));  // every lane is active again after the loop
}

// for (k < 10) { if (odd lane && k < 5) continue; d += 1; } ++k sits before
// the continue, as GLSL IR places a for loop's increment.
TEST(ControlFlow, ContinueSkipsTheRestOfOnePass) {
    Exec exec;
    const Mask odd = Mask::from_bits(0xaaaau);
    Float d = 0.0f;
    Int k = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(k < Int(10)));
        exec.assign(k, k + 1);
        loop.continue_if(odd && k < Int(6));
        exec.assign(d, d + 1.0f);
    });
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(d[lane], lane % 2 ? 5.0f : 10.0f);
}

// E3: a lane that discards inside a long loop leaves it at the end of the
// pass (GLSL >= 1.30), so its group's next loop runs in full.
TEST(ControlFlow, DiscardLeavesLoopsAndSparesTheBudget) {
    Exec exec;
    Int n = 10;
    n = select(Mask::from_bits(1), Int(1000000), n);
    Float d = 0.0f;
    Int k = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(k < n));
        exec.if_(k == Int(3) && n > Int(100), [&] { exec.discard(); });
        exec.assign(d, d + 1.0f);
        exec.assign(k, k + 1);
    });
    const Float second = count(exec, Int(100));
    EXPECT_EQ(bits(exec.discarded()), 1u);
    EXPECT_EQ(d[0], 4.0f);       // the pass that discarded ran to its end
    EXPECT_EQ(second[0], 1.0f);  // a discarded lane leaves every loop after one pass
    for (int lane = 1; lane < kLanes; ++lane) {
        EXPECT_EQ(d[lane], 10.0f) << lane;
        EXPECT_EQ(second[lane], 100.0f) << lane;  // the budget was not spent
    }
}

// A loop in an if that no lane takes still runs one pass and spends it.
TEST(ControlFlow, IfRunsBothSidesAndMasksOnlyStores) {
    Exec exec;
    const Mask low = Mask::from_bits(0x0f0fu);
    Float v = 1.0f, w = 0.0f;
    exec.if_else(low, [&] { exec.assign(v, v * 3.0f); }, [&] { exec.assign(w, v + 5.0f); });
    for (int lane = 0; lane < kLanes; ++lane) {
        const bool in = (0x0f0fu >> lane) & 1;
        EXPECT_EQ(v[lane], in ? 3.0f : 1.0f);
        EXPECT_EQ(w[lane], in ? 0.0f : 6.0f);
    }
    Float d = 0.0f;
    exec.if_(Mask(false), [&] { d = count(exec, Int(5)); });
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(d[lane], 0.0f);
    // 65535 - 1 passes left: a 70000-pass loop now stops one pass earlier.
    const Float c = count(exec, Int(70000));
    EXPECT_EQ(c[0], 65534.0f);
}

}  // namespace st
