// control_flow.h: GLSL control flow over lanes, as llvmpipe executes it
// (docs/llvmpipe/lanes-and-control-flow.md §3-§5).
//
// A fragment twin runs every statement on all lanes. What control flow
// changes is which lanes a *store* reaches: `Exec` holds the execution mask
// (llvmpipe's exec mask: all ones at the top of main(), narrowed by if,
// break and continue, never by coverage), and a twin writes a variable that
// is assigned under control flow with exec.assign(var, value), the masked
// store select(exec, value, var) llvmpipe emits for a NIR register. Values
// computed inside a branch or loop and not stored stay unmasked, as NIR SSA
// values are: inactive lanes compute them too, from their own (frozen)
// variables, which is what a neighbour's dFdx or implicit LOD sees.
//
// A GLSL loop and its twin line up statement by statement:
//
//   for (int i = 0; i < steps; ++i) {        Int i = 0;
//       if (h > depth) break;                exec.loop([&](Loop& loop) {
//       depth += dz;                             loop.break_if(!(i < Int(steps)));
//   }                                            loop.break_if(h > depth);
//                                                exec.assign(depth, depth + dz);
//                                                exec.assign(i, i + 1);
//                                            });
//
// `for` becomes a loop whose first statement breaks on the negated
// condition, as GLSL IR writes it, so a loop that runs its body n times
// runs n + 1 passes, the last of which only breaks. Loops end when no lane
// of an 8-lane group (one llvmpipe vector) is left in them, and every pass
// of every loop spends one unit of a budget of 65535 passes per group and
// invocation; when it is spent, each loop ends after its current pass and
// its lanes carry on after it. Loops GLSL unrolls (a constant trip count
// of at most 32) cost nothing there and are plain C++ loops in a twin.
//
// `discard` clears only the fragment's coverage (FragmentResult::discarded);
// the lane keeps running as a helper. With #version 130 and later, Mesa's
// linker makes a discarded lane leave every loop at the end of its current
// pass (lower_discard_flow), which matters through the budget.
#pragma once

#include <array>

#include "simd/lane_vec.h"

namespace st {

class Exec;

// The state of one loop: which lanes entered it, which have left (break,
// or their group's budget ran out) and which skip the rest of this pass
// (continue).
class Loop {
public:
    // GLSL `if (c) break;`: active lanes where c holds leave the loop.
    void break_if(Mask c);
    // GLSL `if (c) continue;`: active lanes where c holds skip to the end
    // of this pass.
    void continue_if(Mask c);
    // GLSL `break;` and `continue;` where they stand (inside an exec.if_).
    void break_() { break_if(Mask(true)); }
    void continue_() { continue_if(Mask(true)); }

private:
    friend class Exec;
    Loop(Exec& exec, Mask entry) : exec_(exec), entry_(entry) {}
    void update() const;

    Exec& exec_;
    Mask entry_;
    Mask left_{false};
    Mask continued_{false};
};

class Exec {
public:
    // Passes per 8-lane group and invocation (LP_MAX_TGSI_LOOP_ITERATIONS).
    static constexpr int kLoopBudget = 65535;

    Exec() { budget_.fill(kLoopBudget); }

    // The lanes a store reaches now.
    Mask active() const { return cond_ && loop_; }

    // A store to a variable under control flow (a NIR register).
    template <class T> void assign(T& variable, const T& value) const {
        variable = select(active(), value, variable);
    }

    // GLSL `if (c) { then(); }` and `if (c) { then(); } else { otherwise(); }`.
    // Both sides run on every lane, whatever the mask (llvmpipe emits no
    // branch), so a loop in a side no lane takes still spends its pass.
    template <class Then> void if_(Mask c, Then&& then) {
        const Mask saved = cond_;
        cond_ = saved && c;
        then();
        cond_ = saved;
    }
    template <class Then, class Else> void if_else(Mask c, Then&& then, Else&& otherwise) {
        const Mask saved = cond_;
        cond_ = saved && c;
        then();
        cond_ = and_not(saved, c);
        otherwise();
        cond_ = saved;
    }

    // A GLSL loop: body(Loop&) is one pass.
    template <class Body> void loop(Body&& body);

    // GLSL `discard` (in the current control flow) and `if (c) discard;`.
    void discard() { discarded_ = discarded_ || active(); }
    void discard_if(Mask c) { discarded_ = discarded_ || (active() && c); }
    Mask discarded() const { return discarded_; }

private:
    friend class Loop;
    static constexpr int kGroups = kLanes / 8;

    // Ends a pass: discarded lanes leave, each group still looping spends
    // one pass of its budget and stops when no lane of it is left or the
    // budget is gone. Returns whether any group goes on.
    bool end_pass(Loop& loop);

    Mask cond_{true};   // enclosing ifs
    Mask loop_{true};   // enclosing loops: entered, not left, not continued
    Mask discarded_{false};
    // Lane bits of the groups whose vector still executes this code: a group
    // that has finished a loop no longer runs (or pays for) the passes the
    // other group makes in it.
    unsigned running_ = (1u << kLanes) - 1;
    std::array<int, kGroups> budget_;
};

inline void Loop::update() const { exec_.loop_ = and_not(and_not(entry_, left_), continued_); }

inline void Loop::break_if(Mask c) {
    left_ = left_ || (exec_.active() && c);
    update();
}

inline void Loop::continue_if(Mask c) {
    continued_ = continued_ || (exec_.active() && c);
    update();
}

template <class Body> void Exec::loop(Body&& body) {
    const Mask saved = loop_;
    const unsigned saved_running = running_;
    Loop state(*this, active());
    do {
        state.continued_ = Mask(false);
        state.update();
        body(state);
    } while (end_pass(state));
    loop_ = saved;
    running_ = saved_running;
}

inline bool Exec::end_pass(Loop& loop) {
    loop.left_ = loop.left_ || (loop.entry_ && discarded_);
    const unsigned in_loop = bits(and_not(loop.entry_, loop.left_));
    for (int g = 0; g < kGroups; ++g) {
        const unsigned lanes = 0xffu << (8 * g);
        if (!(running_ & lanes)) continue;
        // lp_exec_endloop: decrement, then go round again only if a lane is
        // left and the budget is still positive.
        if (--budget_[size_t(g)] <= 0 || !(in_loop & lanes)) running_ &= ~lanes;
    }
    loop.left_ = loop.left_ || !Mask::from_bits(running_);
    return running_ != 0;
}

}  // namespace st
