// The engine's job system: every index runs exactly once, a call returns only after all its
// tasks have, work spreads over the threads, and --threads 0 means the hardware's count.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "game/JobSystem.h"

using cube::JobSystem;

namespace jobsystem_test {

struct Counters {
    std::unique_ptr<std::atomic<int>[]> hits;
    explicit Counters(uint32_t n) : hits(new std::atomic<int>[n]) {
        for (uint32_t i = 0; i < n; ++i) hits[i].store(0);
    }
    static void task(void* data, uint32_t i) { static_cast<Counters*>(data)->hits[i].fetch_add(1); }
};

/// Tasks that wait, inside the call, until `want` distinct threads have entered one (or a
/// timeout passes): only a job system that really runs them at once gets past the wait early.
struct Meeting {
    std::mutex mutex;
    std::condition_variable cv;
    std::set<std::thread::id> threads;
    size_t want = 2;
    bool timedOut = false;
    std::atomic<int> calls{0};
    static void task(void* data, uint32_t) {
        Meeting& m = *static_cast<Meeting*>(data);
        m.calls.fetch_add(1);
        std::unique_lock<std::mutex> lock(m.mutex);
        m.threads.insert(std::this_thread::get_id());
        m.cv.notify_all();
        if (!m.cv.wait_for(lock, std::chrono::seconds(20), [&] { return m.threads.size() >= m.want; }))
            m.timedOut = true;
    }
};

}  // namespace jobsystem_test

using jobsystem_test::Counters;
using jobsystem_test::Meeting;

TEST(JobSystem, EveryIndexRunsExactlyOnce) {
    for (int threads : {1, 2, 8}) {
        JobSystem jobs(threads);
        EXPECT_EQ(jobs.threads(), threads);
        for (uint32_t count : {2u, 3u, 7u, 64u, 100000u}) {
            SCOPED_TRACE(testing::Message() << threads << " threads, count " << count);
            Counters c(count);
            jobs.parallelFor(count, &Counters::task, &c);
            uint32_t wrong = 0;
            for (uint32_t i = 0; i < count; ++i) wrong += c.hits[i].load() != 1;
            EXPECT_EQ(wrong, 0u);
        }
    }
}

TEST(JobSystem, CountZeroCallsNothingAndCountOneRunsOnTheCaller) {
    JobSystem jobs(8);
    struct Seen {
        int calls = 0;
        uint32_t index = 99;
        std::thread::id thread;
    } seen;
    auto task = [](void* data, uint32_t i) {
        Seen& s = *static_cast<Seen*>(data);
        ++s.calls;
        s.index = i;
        s.thread = std::this_thread::get_id();
    };
    jobs.parallelFor(0, task, &seen);
    EXPECT_EQ(seen.calls, 0);
    jobs.parallelFor(1, task, &seen);
    EXPECT_EQ(seen.calls, 1);
    EXPECT_EQ(seen.index, 0u);
    EXPECT_EQ(seen.thread, std::this_thread::get_id());
}

TEST(JobSystem, OneThreadRunsEveryIndexInOrderOnTheCaller) {
    JobSystem jobs(1);
    struct Order {
        std::vector<uint32_t> indices;
        bool otherThread = false;
        std::thread::id caller = std::this_thread::get_id();
    } order;
    order.indices.reserve(100);
    jobs.parallelFor(100, [](void* data, uint32_t i) {
        Order& o = *static_cast<Order*>(data);
        o.indices.push_back(i);
        o.otherThread |= std::this_thread::get_id() != o.caller;
    }, &order);
    ASSERT_EQ(order.indices.size(), 100u);
    for (uint32_t i = 0; i < 100; ++i) EXPECT_EQ(order.indices[i], i);
    EXPECT_FALSE(order.otherThread);
}

// Back-to-back calls, some of whose tasks sleep, so the last task to finish is often a worker's:
// every slot a call's tasks write (plain ints, no atomics) holds that call's value right after it
// returns, and the run does not hang.
TEST(JobSystem, BackToBackCallsEachReturnAfterAllTheirTasks) {
    constexpr uint32_t kCount = 8;
    JobSystem jobs(4);
    struct Slots {
        int call = 0;
        int value[kCount] = {};
    } slots;
    int stale = 0;
    for (int call = 1; call <= 2000; ++call) {
        slots.call = call;
        jobs.parallelFor(kCount, [](void* data, uint32_t i) {
            Slots& s = *static_cast<Slots*>(data);
            if (int(i) % 3 == s.call % 3) std::this_thread::sleep_for(std::chrono::microseconds(20));
            s.value[i] = s.call;
        }, &slots);
        for (uint32_t i = 0; i < kCount; ++i) stale += slots.value[i] != call;
    }
    EXPECT_EQ(stale, 0);
}

TEST(JobSystem, TasksRunOnMoreThanOneThread) {
    for (int threads : {2, 8}) {
        SCOPED_TRACE(testing::Message() << threads << " threads");
        JobSystem jobs(threads);
        Meeting m;
        const uint32_t count = uint32_t(threads) * 2;
        jobs.parallelFor(count, &Meeting::task, &m);
        EXPECT_FALSE(m.timedOut) << "no second thread entered a task within 20 s";
        EXPECT_GE(m.threads.size(), 2u);
        EXPECT_EQ(m.calls.load(), int(count));
    }
}

TEST(JobSystem, ThreadCountZeroMeansTheHardwareCappedAt64) {
    const int hardware = std::clamp(int(std::thread::hardware_concurrency()), 1, JobSystem::kMaxThreads);
    EXPECT_EQ(JobSystem::resolveThreads(0), hardware);
    EXPECT_EQ(JobSystem::resolveThreads(-1), hardware);
    EXPECT_EQ(JobSystem::resolveThreads(1), 1);
    EXPECT_EQ(JobSystem::resolveThreads(5), 5);
    EXPECT_EQ(JobSystem::resolveThreads(64), 64);
    EXPECT_EQ(JobSystem::resolveThreads(65), 64);
    EXPECT_EQ(JobSystem::resolveThreads(100000), 64);
    EXPECT_EQ(JobSystem(JobSystem::resolveThreads(0)).threads(), hardware);
    EXPECT_EQ(JobSystem(1000).threads(), 64);
    EXPECT_EQ(JobSystem(0).threads(), 1);
}

// Made and destroyed without a call, and right after one: the destructor wakes and joins every
// worker (a hang here is the failure).
TEST(JobSystem, ShutsDownCleanlyWithAndWithoutWork) {
    for (int round = 0; round < 50; ++round) {
        JobSystem idle(8);
        JobSystem used(8);
        Counters c(256);
        used.parallelFor(256, &Counters::task, &c);
        EXPECT_EQ(c.hits[255].load(), 1);
    }
}
