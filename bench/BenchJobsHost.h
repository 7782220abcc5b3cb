#pragma once
// A host for the benchmarks whose job system (HostAdapter::parallelFor) is the engine's
// cube::JobSystem of `threads` threads: what a game hands the plugin (bench_draw, bench_sim).
#include "fx/HostAdapter.h"
#include "game/JobSystem.h"

namespace bench {

class JobsHost final : public fx::HostAdapter {
public:
    explicit JobsHost(int threads) : jobs_(threads) {}
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return 0; }
    fx::WheelContact wheel(int) const override { return fx::WheelContact{}; }
    void log(fx::LogLevel, const char*) override {}
    void parallelFor(uint32_t count, Task task, void* data) override { jobs_.parallelFor(count, task, data); }

private:
    cube::JobSystem jobs_;
};

}  // namespace bench
