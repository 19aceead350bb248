// memory_budget_test.cpp: sizes on the command line, and estimates that grow
// with what a frame draws.
#include "app/memory_budget.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace st {

TEST(MemoryBudget, ParsesSizes) {
    EXPECT_EQ(parse_memory_size("4G"), 4ull << 30);
    EXPECT_EQ(parse_memory_size("512M"), 512ull << 20);
    EXPECT_EQ(parse_memory_size("1.5GiB"), 3ull << 29);
    EXPECT_EQ(parse_memory_size("800000K"), 800000ull << 10);
    EXPECT_EQ(parse_memory_size("123456789"), 123456789ull);
    for (const char* bad : {"", "G", "12Q", "-1G", "0", "nan", "inf", "1e30T", "4 G"})
        EXPECT_THROW(parse_memory_size(bad), std::invalid_argument) << bad;
}

TEST(MemoryBudget, EstimateGrowsWithPixelsAndBackends) {
    auto frame_of = [](int size) {
        Frame f;
        Pass p;
        p.width = p.height = size;
        f.passes.push_back(p);
        return f;
    };
    const uint64_t small = estimate_memory(frame_of(256), MemoryUse::Compare);
    const uint64_t large = estimate_memory(frame_of(4096), MemoryUse::Compare);
    // 4096^2 - 256^2 more pixels at no less than the 119 bytes measured for compare.
    EXPECT_GE(large - small, uint64_t(119.0 * (4096.0 * 4096 - 256.0 * 256)));
    EXPECT_LT(estimate_memory(frame_of(4096), MemoryUse::RenderCpu), large);
}

TEST(MemoryBudget, MaxMemoryIsTheBudgetWhenSmallest) {
    const MemoryBudget b = memory_budget(64ull << 20);
    EXPECT_EQ(b.resident, 64ull << 20);
    EXPECT_EQ(b.source, "--max-memory");
    EXPECT_GT(memory_budget(0).resident, 64ull << 20);
}

TEST(MemoryBudget, Figures) {
    EXPECT_EQ(memory_figure(512ull << 20), "512 MiB");
    EXPECT_EQ(memory_figure((128ull << 30) / 10), "12.8 GiB");
}

}  // namespace st
