// worker_pool_test.cpp: every index of a run is done exactly once, by a
// worker in range, whatever the thread count, inside a frame scope (workers
// awake between runs) and outside it (workers asleep between runs).
#include "raster/worker_pool.h"

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace st {
namespace {

void expect_each_index_once(WorkerPool& pool, int count) {
    std::vector<std::atomic<int>> runs(static_cast<size_t>(count));
    std::atomic<bool> bad_worker{false};
    pool.run(count, [&](int i, int worker) {
        if (worker < 0 || worker >= pool.size()) bad_worker = true;
        runs[size_t(i)].fetch_add(1, std::memory_order_relaxed);
    });
    EXPECT_FALSE(bad_worker);
    for (int i = 0; i < count; ++i) ASSERT_EQ(runs[size_t(i)].load(), 1) << "index " << i << " of " << count;
}

TEST(WorkerPool, EachIndexOnceAtEveryThreadCount) {
    for (int threads : {1, 2, 3, 8}) {
        WorkerPool pool(threads);
        EXPECT_EQ(pool.size(), threads);
        for (int count : {0, 1, 2, 7, 64, 1000}) expect_each_index_once(pool, count);
    }
}

TEST(WorkerPool, RunsBackToBackInsideAFrame) {
    WorkerPool pool(3);
    for (int frame = 0; frame < 50; ++frame) {
        const WorkerPool::Frame awake(pool);
        for (int step = 0; step < 3; ++step) expect_each_index_once(pool, 17 + step);
    }
}

TEST(WorkerPool, AFrameWithoutRunsAndRunsAfterSleeping) {
    WorkerPool pool(2);
    { const WorkerPool::Frame awake(pool); }  // woken, nothing to do
    // Long enough for the workers to stop spinning and sleep.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    expect_each_index_once(pool, 64);
    {
        const WorkerPool::Frame awake(pool);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));  // a serial step
        expect_each_index_once(pool, 64);
    }
}

TEST(WorkerPool, BothWorkersTakePartWhenJobsWait) {
    // With jobs that each wait for the other worker, a run of two completes
    // only if a second thread picks one up.
    WorkerPool pool(2);
    const WorkerPool::Frame awake(pool);
    std::atomic<int> arrived{0};
    pool.run(2, [&](int, int) {
        arrived.fetch_add(1);
        while (arrived.load() < 2) std::this_thread::yield();
    });
    EXPECT_EQ(arrived.load(), 2);
}

}  // namespace
}  // namespace st
