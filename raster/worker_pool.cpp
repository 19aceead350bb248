// worker_pool.cpp: indices handed out one at a time under a mutex; jobs are
// tiles or vertex ranges, coarse enough that the lock is not the bottleneck.
// A frame runs a few jobs back to back (vertices, setup, tiles), so a worker
// that finishes one, and the caller waiting for the last, watch for the next
// step before they sleep (for the whole frame inside begin_frame() and
// end_frame(), else for a moment): a futex wake-up costs tens of
// microseconds, a sizeable part of a 2 ms frame.
#include "raster/worker_pool.h"

#include <chrono>

#include "raster/float_env.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace st {

namespace {

// Spins until done(), for about 20 microseconds or, while longer() holds,
// up to 10 ms (a frame's serial steps are far shorter; the bound keeps a
// caller that forgets end_frame() from spinning for ever); true when done().
template <class Done, class Longer>
bool spin_briefly(Done done, Longer longer) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 1;; ++i) {
        if (done()) return true;
#if defined(__x86_64__)
        _mm_pause();
#endif
        if (i % 64 == 0) {
            const auto spun = std::chrono::steady_clock::now() - start;
            if (spun > std::chrono::milliseconds(10) || (spun > std::chrono::microseconds(20) && !longer()))
                return false;
        }
    }
}

}  // namespace

WorkerPool::WorkerPool(int threads) {
    for (int w = 1; w < threads; ++w) threads_.emplace_back([this, w] { work(w); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
}

void WorkerPool::drain(int worker) {
    std::unique_lock lock(mutex_);
    while (next_ < count_) {
        const int index = next_++;
        ++busy_;
        lock.unlock();
        (*job_)(index, worker);
        lock.lock();
        --busy_;
    }
    if (busy_ == 0) {
        finished_.store(generation_, std::memory_order_release);
        done_.notify_all();
    }
}

void WorkerPool::work(int worker) {
    const FlushDenormals float_env;  // workers only ever render
    unsigned seen = 0, frames_seen = 0;
    auto in_frame = [this] { return in_frame_.load(std::memory_order_relaxed); };
    for (;;) {
        spin_briefly([&] { return published_.load(std::memory_order_acquire) != seen; }, in_frame);
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen || frames_begun_ != frames_seen; });
            if (stop_) return;
            frames_seen = frames_begun_;
            if (generation_ == seen) continue;  // a frame began: watch for its first run
            seen = generation_;
        }
        drain(worker);
    }
}

void WorkerPool::begin_frame() {
    if (threads_.empty()) return;
    {
        std::lock_guard lock(mutex_);
        ++frames_begun_;
        in_frame_.store(true, std::memory_order_relaxed);
    }
    wake_.notify_all();
}

void WorkerPool::end_frame() { in_frame_.store(false, std::memory_order_relaxed); }

void WorkerPool::run(int count, const std::function<void(int, int)>& job) {
    // One job (a draw of a few vertices, a pass of one chunk) is not worth
    // waking anyone for.
    if (count <= 1 || threads_.empty()) {
        for (int i = 0; i < count; ++i) job(i, 0);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        job_ = &job;
        count_ = count;
        next_ = 0;
        ++generation_;
        published_.store(generation_, std::memory_order_release);
    }
    wake_.notify_all();
    drain(0);
    const unsigned generation = published_.load(std::memory_order_relaxed);
    spin_briefly([&] { return finished_.load(std::memory_order_acquire) == generation; }, [] { return false; });
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return next_ >= count_ && busy_ == 0; });
    job_ = nullptr;
}

}  // namespace st
