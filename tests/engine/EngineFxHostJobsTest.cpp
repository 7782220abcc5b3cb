// EngineFxHost::parallelFor (fx::HostAdapter, API 2.2) runs the plugin's tasks on the engine's
// job system when it has one, and in order on the calling thread when it has none; Game sizes
// that job system from --threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "GameTestUtil.h"
#include "game/EngineFxHost.h"
#include "game/Game.h"
#include "game/JobSystem.h"

namespace enginefxhost_test {

/// Each call records its index and thread, then waits (up to 20 s) until two distinct threads
/// have entered a call: only tasks that really run at once get past it early.
struct Calls {
    std::mutex mutex;
    std::condition_variable cv;
    std::vector<uint32_t> indices;
    std::set<std::thread::id> threads;
    bool wait = true;
    bool timedOut = false;
    static void task(void* data, uint32_t i) {
        Calls& c = *static_cast<Calls*>(data);
        std::unique_lock<std::mutex> lock(c.mutex);
        c.indices.push_back(i);
        c.threads.insert(std::this_thread::get_id());
        c.cv.notify_all();
        if (c.wait && !c.cv.wait_for(lock, std::chrono::seconds(20), [&] { return c.threads.size() >= 2; }))
            c.timedOut = true;
    }
};

}  // namespace enginefxhost_test

using enginefxhost_test::Calls;

TEST(EngineFxHost, ParallelForRunsOnTheJobSystemItWasGiven) {
    cube::JobSystem jobs(2);
    cube::EngineFxHost host(nullptr, nullptr, &jobs);
    fx::HostAdapter& adapter = host;  // as the plugin calls it
    Calls calls;
    adapter.parallelFor(4, &Calls::task, &calls);
    EXPECT_FALSE(calls.timedOut) << "the tasks never ran on two threads at once";
    EXPECT_EQ(calls.threads.size(), 2u);
    std::vector<uint32_t> sorted = calls.indices;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, (std::vector<uint32_t>{0, 1, 2, 3}));
}

TEST(EngineFxHost, WithoutAJobSystemParallelForRunsInOrderOnTheCaller) {
    cube::EngineFxHost host(nullptr, nullptr);
    fx::HostAdapter& adapter = host;
    Calls calls;
    calls.wait = false;
    adapter.parallelFor(5, &Calls::task, &calls);
    EXPECT_EQ(calls.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4}));
    ASSERT_EQ(calls.threads.size(), 1u);
    EXPECT_EQ(*calls.threads.begin(), std::this_thread::get_id());
}

TEST(Game, ThreadsOptionSizesTheJobSystem) {
    for (int threads : {1, 3, 0}) {
        SCOPED_TRACE(threads);
        cube::Options o = cubetest::sceneOnlyOptions(64, 64);
        o.threads = threads;
        cube::Game game;
        std::string err;
        ASSERT_TRUE(game.Init(o, &err)) << err;
        ASSERT_NE(game.jobs(), nullptr);
        EXPECT_EQ(game.jobs()->threads(), cube::JobSystem::resolveThreads(threads));
    }
}
