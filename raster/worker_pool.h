// worker_pool.h: a fixed set of threads that run indexed jobs.
//
// run(n, job) calls job(i, worker) once for every i in [0, n) and returns when
// all are done. Which worker runs which index is not fixed, so a job must
// write only to state owned by its index (a tile, a vertex range): that is
// what keeps images independent of thread count and scheduling.
//
// A frame is a few runs back to back with short serial steps between them
// (a small vertex stage, sorting the tiles). Between begin_frame() and
// end_frame() the workers are awake and watch for the next run instead of
// sleeping, so no run waits for a futex wake-up (tens of microseconds, a
// few percent of a 2-thread frame); begin_frame() wakes them at once, so
// that their wake-up overlaps the frame's first serial step.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace st {

class WorkerPool {
public:
    explicit WorkerPool(int threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int size() const { return int(threads_.size()) + 1; }  // the caller works too
    void run(int count, const std::function<void(int index, int worker)>& job);

    void begin_frame();
    void end_frame();
    // begin_frame() ... end_frame() for a scope.
    class Frame {
    public:
        explicit Frame(WorkerPool& pool) : pool_(pool) { pool_.begin_frame(); }
        ~Frame() { pool_.end_frame(); }
        Frame(const Frame&) = delete;
        Frame& operator=(const Frame&) = delete;

    private:
        WorkerPool& pool_;
    };

private:
    void work(int worker);
    void drain(int worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(int, int)>* job_ = nullptr;
    int count_ = 0, next_ = 0, busy_ = 0;
    unsigned generation_ = 0;
    std::atomic<unsigned> published_{0};  // generation_, readable without the lock
    std::atomic<unsigned> finished_{0};   // the last generation whose jobs are all done
    bool stop_ = false;
    unsigned frames_begun_ = 0;         // wakes sleeping workers when it changes
    std::atomic<bool> in_frame_{false};  // between begin_frame() and end_frame()
};

}  // namespace st
