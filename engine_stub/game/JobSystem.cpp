#include "game/JobSystem.h"

#include <algorithm>
#include <system_error>

namespace cube {

namespace {

// How long a thread polls before it sleeps: a few tens of microseconds, enough to catch the next
// of the plugin's back-to-back calls in one view without a wake-up, too short to matter to the
// driver's threads between frames.
constexpr int kSpinIterations = 2000;

inline void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
}

}  // namespace

int JobSystem::resolveThreads(int requested) {
    int n = requested;
    if (n <= 0) n = int(std::min(std::thread::hardware_concurrency(), unsigned(kMaxThreads)));
    return std::clamp(n, 1, kMaxThreads);
}

JobSystem::JobSystem(int threads) {
    const int workers = std::clamp(threads, 1, kMaxThreads) - 1;
    workers_.reserve(size_t(workers));
    for (int i = 0; i < workers; ++i) {
        try {
            workers_.emplace_back([this] { workerLoop(); });
        } catch (const std::system_error&) {
            break;  // fewer threads than asked for still runs every call
        }
    }
}

JobSystem::~JobSystem() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

void JobSystem::drain(Task task, void* data, uint32_t count, std::atomic<uint64_t>& next,
                      std::atomic<uint32_t>& finished) {
    for (uint64_t i = next.fetch_add(1, std::memory_order_relaxed); i < count;
         i = next.fetch_add(1, std::memory_order_relaxed)) {
        task(data, uint32_t(i));
        // release: what the task wrote is visible to the caller once it sees the count.
        finished.fetch_add(1, std::memory_order_release);
    }
}

void JobSystem::parallelFor(uint32_t count, Task task, void* data) {
    if (count == 0) return;
    if (count == 1 || workers_.empty()) {
        for (uint32_t i = 0; i < count; ++i) task(data, i);
        return;
    }
    {
        std::unique_lock<std::mutex> lock(mutex_);
        // A worker that joined the last call after its indices ran out may still be about to
        // make its last claim on next_: let it leave before next_ starts over.
        done_.wait(lock, [this] { return active_ == 0; });
        task_ = task;
        data_ = data;
        count_ = count;
        next_.store(0, std::memory_order_relaxed);
        finished_.store(0, std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    drain(task, data, count, next_, finished_);
    // Every index is claimed; wait until the workers' last calls have returned.
    auto allDone = [this, count] { return finished_.load(std::memory_order_acquire) == count; };
    for (int spin = 0; spin < kSpinIterations && !allDone(); ++spin) cpuRelax();
    if (!allDone()) {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, allDone);
    }
}

void JobSystem::workerLoop() {
    uint64_t seen = 0;
    for (;;) {
        for (int spin = 0; spin < kSpinIterations && generation_.load(std::memory_order_acquire) == seen; ++spin)
            cpuRelax();
        Task task = nullptr;
        void* data = nullptr;
        uint32_t count = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_.load(std::memory_order_relaxed) != seen; });
            if (stop_) return;
            seen = generation_.load(std::memory_order_relaxed);
            task = task_;
            data = data_;
            count = count_;
            ++active_;
        }
        drain(task, data, count, next_, finished_);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            --active_;
        }
        // The caller waits on done_ for the last index to finish (or, at its next call, for
        // active_ to reach 0); both changed before this.
        done_.notify_all();
    }
}

}  // namespace cube
