#pragma once
// Hosts whose job system (HostAdapter::parallelFor) runs the plugin's pieces in the ways a host
// might: on several threads at once, in reverse, each twice, or dropping every other one (the
// plugin must give the same results under each: ParallelBuildTest, ParallelStepTest).
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "fx/HostAdapter.h"

namespace jobhost_test {

enum class HowRun { Threads, Reversed, Twice, DropOdd };

// A host whose job system runs the pieces as `how` says, and counts what it was asked.
class JobHost final : public fx::HostAdapter {
public:
    explicit JobHost(HowRun how) : how_(how) {}
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return 0; }
    fx::WheelContact wheel(int) const override { return fx::WheelContact{}; }
    void log(fx::LogLevel, const char*) override {}
    void parallelFor(uint32_t count, Task task, void* data) override {
        ++calls;
        largest = std::max(largest, count);
        switch (how_) {
            case HowRun::Threads: {
                std::atomic<uint32_t> next{0};
                std::vector<std::thread> threads;
                for (int t = 0; t < 4; ++t) {
                    threads.emplace_back([&]() {
                        for (uint32_t i; (i = next.fetch_add(1)) < count;) task(data, i);
                    });
                }
                for (std::thread& t : threads) t.join();
                break;
            }
            case HowRun::Reversed:
                for (uint32_t i = count; i-- > 0;) task(data, i);
                break;
            case HowRun::Twice:
                for (uint32_t i = 0; i < count; ++i) task(data, i);
                for (uint32_t i = 0; i < count; ++i) task(data, i);
                break;
            case HowRun::DropOdd:
                for (uint32_t i = 0; i < count; i += 2) task(data, i);
                break;
        }
    }
    int calls = 0;
    uint32_t largest = 0;

private:
    HowRun how_;
};

const HowRun kRuns[] = {HowRun::Threads, HowRun::Reversed, HowRun::Twice, HowRun::DropOdd};

}  // namespace jobhost_test
