#pragma once
// The engine's job system: a fixed set of worker threads that run the pieces of one parallelFor
// beside the thread that calls it. The smoke plugin reaches it through EngineFxHost::parallelFor
// (fx::HostAdapter, API 2.2) for its per-view culling, sorting and bounding.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace cube {

/// Contract:
///  - parallelFor is called from one thread at a time (the frame thread); it is not re-entrant:
///    a task must not call parallelFor.
///  - A task must not throw: a worker that lets an exception out ends the program.
///  - Between calls the workers sleep on a condition variable (after a short spin), so an idle
///    job system leaves the cores to the GL driver (llvmpipe rasterises on them).
///  - No allocation per call; the workers are made in the constructor and joined in the destructor.
class JobSystem {
public:
    using Task = void (*)(void* data, uint32_t index);
    static constexpr int kMaxThreads = 64;

    /// `threads` in all, the calling thread included: 1 = no workers, every call runs inline.
    /// Values outside [1, kMaxThreads] are clamped. Where the system refuses to start a thread,
    /// the job system runs with the workers it got (threads() says how many).
    explicit JobSystem(int threads);
    ~JobSystem();
    JobSystem(const JobSystem&) = delete;
    JobSystem& operator=(const JobSystem&) = delete;

    /// Calls task(data, i) once for every i in [0, count), on the calling thread and the workers,
    /// and returns when every call has returned. Indices are handed out one at a time through an
    /// atomic counter, so a slow piece does not hold back the others. count 0 returns at once;
    /// count 1, or a job system of one thread, runs the tasks inline in order.
    void parallelFor(uint32_t count, Task task, void* data);

    /// Threads taking part in a call, the caller included (1..kMaxThreads).
    int threads() const { return int(workers_.size()) + 1; }

    /// The thread count a `--threads N` request means: N <= 0 = one per hardware thread
    /// (std::thread::hardware_concurrency(), 1 where it is unknown); at most kMaxThreads.
    static int resolveThreads(int requested);

private:
    void workerLoop();
    /// Claims and runs indices of the current call until none are left.
    static void drain(Task task, void* data, uint32_t count, std::atomic<uint64_t>& next,
                      std::atomic<uint32_t>& finished);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;  ///< workers: a new call (generation_) or stop_
    std::condition_variable done_;  ///< caller: a worker left a call
    // The current call, written under mutex_ before generation_ moves on; workers copy it under
    // mutex_ when they join the call.
    Task task_ = nullptr;
    void* data_ = nullptr;
    uint32_t count_ = 0;
    std::atomic<uint64_t> generation_{0};  ///< written under mutex_; read without it while spinning
    int active_ = 0;                       ///< workers inside a call (under mutex_)
    bool stop_ = false;                    ///< under mutex_
    // 64 bits: each thread overshoots count by one claim, so a 32-bit counter could wrap.
    std::atomic<uint64_t> next_{0};
    std::atomic<uint32_t> finished_{0};
};

}  // namespace cube
