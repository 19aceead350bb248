// worker_pool.cpp: indices handed out one at a time under a mutex; jobs are
// tiles or vertex ranges, coarse enough that the lock is not the bottleneck.
#include "raster/worker_pool.h"

#include "raster/float_env.h"

namespace st {

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
    if (busy_ == 0) done_.notify_all();
}

void WorkerPool::work(int worker) {
    const FlushDenormals float_env;  // workers only ever render
    unsigned seen = 0;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
        }
        drain(worker);
    }
}

void WorkerPool::run(int count, const std::function<void(int, int)>& job) {
    {
        std::lock_guard lock(mutex_);
        job_ = &job;
        count_ = count;
        next_ = 0;
        ++generation_;
    }
    wake_.notify_all();
    drain(0);
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return next_ >= count_ && busy_ == 0; });
    job_ = nullptr;
}

}  // namespace st
