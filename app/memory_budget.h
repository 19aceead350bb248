// memory_budget.h: the memory a command will need, checked before it starts
// against what this process may use, so that a scene too large for the
// machine is refused with the figures instead of failing half-way (as
// "std::bad_alloc" or llvmpipe's "incomplete framebuffer").
//
// The estimate is of the process's peak resident memory while one scene is
// rendered: what is resident when the check runs (the loaded scenes), the
// GL and LLVM runtime's own, and per pixel, texel and vertex what each
// backend, the written images and the comparison hold at once. Its
// constants are measured (docs/reliability.md); cli.compare_builtin and
// cli.memory check that every scene's measured peak stays within it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frame/frame.h"

namespace st {

struct Scene;

enum class MemoryUse { RenderCpu, RenderGl, Compare, BothBackends };

// Peak resident bytes while `frame` is rendered as `use` says (see above).
uint64_t estimate_memory(const Frame& frame, MemoryUse use);

// What this process may still take, and from where that limit comes: the
// smallest of --max-memory (`max_memory`, 0 for none), the cgroup's
// memory.max, MemAvailable and `ulimit -v`.
struct MemoryBudget {
    uint64_t resident = 0;     // bytes of peak resident memory allowed
    std::string source;        // "--max-memory", "MemAvailable", ...
};
MemoryBudget memory_budget(uint64_t max_memory);

// Throws one line naming the first scene whose estimate exceeds the budget,
// with both figures. Nothing has been written when it throws. Returns each
// scene's estimate (for the JSON lines), which adds to estimate_memory()
// what the command keeps of the scenes rendered before it.
std::vector<uint64_t> check_memory(const std::vector<Scene>& scenes, MemoryUse use, uint64_t max_memory);

// "4G", "512M", "1.5G", "800000K" or bytes -> bytes; throws one line.
uint64_t parse_memory_size(const std::string& text);
// 12.8 GiB, 512 MiB: for messages.
std::string memory_figure(uint64_t bytes);

// The process's resident memory now and its peak since the last reset
// (/proc/self/status VmRSS and VmHWM; reset through /proc/self/clear_refs).
uint64_t resident_bytes();
uint64_t peak_resident_bytes();
void reset_peak_resident();

}  // namespace st
