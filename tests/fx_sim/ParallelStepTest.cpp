// ReactionRuntime::step with the host's job system: a pool of tens of thousands is advanced in
// pieces and its dead retired afterwards, and the pool ends the same bit for bit, slot for slot, as
// the one-thread step leaves it, through deaths, the turbulent midpoint step and any way the host
// runs the pieces (JobHosts.h).
#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "JobHosts.h"
#include "../../fx_plugin/sim/ReactionRuntime.h"

namespace {

using jobhost_test::HowRun;
using jobhost_test::JobHost;
using jobhost_test::kRuns;

constexpr float kDt = 1.0f / 60.0f;

// A burst of 40,000 on the first step, lifetimes 0.05 to 0.3 s: a few thousand die each step.
fx::ReactionDesc burstDesc(bool turbulent) {
    fx::ReactionDesc d = fx::defaultReaction(fx::ReactionType::CollisionBurst);
    d.name = turbulent ? "parallel_step_turbulent" : "parallel_step";
    d.emission.capacity = 40000;
    d.emission.burst = 40000;
    d.particle.lifetimeMin = 0.05f;
    d.particle.lifetimeMax = 0.3f;
    d.particle.spreadSpeed = 3.0f;
    if (turbulent) {
        d.turbulence.strength = 2.0f;
        d.turbulence.octaves = 1;  // more octaves run the same code again: 3x the time (under the
                                   // sanitizers 20 of this test's 30 s), nothing more compared
        d.vortex.strength = 1.5f;
    }
    return d;
}

// Every stream of every live slot, and the frames, compared byte for byte.
void expectSamePool(const fx::ParticlePool& a, const fx::ParticlePool& b, int step) {
    ASSERT_EQ(a.alive(), b.alive()) << "step " << step;
    const size_t n = size_t(a.alive());
    for (int s = 0; s < fx::ParticlePool::StreamCount; ++s) {
        const auto stream = static_cast<fx::ParticlePool::Stream>(s);
        ASSERT_EQ(std::memcmp(a.stream(stream), b.stream(stream), n * sizeof(float)), 0) << "stream " << s << ", step " << step;
    }
    ASSERT_EQ(std::memcmp(a.frame(), b.frame(), n), 0) << "step " << step;
}

TEST(ParallelStep, PiecesLeaveThePoolAsOneThreadDoesThroughDeaths) {
    // One pool stepped on the calling thread, and beside it one per way a host runs the pieces,
    // each compared with it after every step.
    const glm::vec3 point(0.0f, 0.5f, 0.0f), wind(0.5f, 0.0f, 0.2f);
    for (bool turbulent : {false, true}) {
        fx::ReactionRuntime serial(burstDesc(turbulent));
        std::vector<std::unique_ptr<JobHost>> hosts;
        std::vector<std::unique_ptr<fx::ReactionRuntime>> pieces;
        for (HowRun how : kRuns) {
            hosts.push_back(std::make_unique<JobHost>(how));
            pieces.push_back(std::make_unique<fx::ReactionRuntime>(burstDesc(turbulent)));
        }
        std::vector<int> callsAfterBurst;
        int minAlive = 0;
        for (int step = 0; step < 20; ++step) {
            const float amount = step == 0 ? 1.0f : 0.0f;  // the burst, then only deaths
            serial.step(kDt, nullptr, 0, amount, point, wind);
            for (size_t k = 0; k < pieces.size(); ++k) {
                pieces[k]->step(kDt, nullptr, 0, amount, point, wind, fx::Jobs(hosts[k].get()));
                expectSamePool(serial.pool(), pieces[k]->pool(), step);
                if (step == 0) callsAfterBurst.push_back(hosts[k]->calls);
            }
            if (step == 0) {
                ASSERT_GT(serial.pool().alive(), 32768);  // at least two pieces
            }
            minAlive = step == 0 ? serial.pool().alive() : std::min(minAlive, serial.pool().alive());
        }
        for (size_t k = 0; k < pieces.size(); ++k) {
            EXPECT_GT(hosts[k]->calls, callsAfterBurst[k]) << "way " << k << ": the steps went through the host's job system";
        }
        EXPECT_LT(minAlive, 10000) << "most of the burst died on the way: the retiring was exercised";
    }
}

TEST(ParallelStep, SmallPoolsAndNoJobSystemStayOnTheCallingThread) {
    fx::ReactionDesc d = burstDesc(false);
    d.emission.capacity = d.emission.burst = 10000;  // one piece
    JobHost host(HowRun::Threads);
    fx::ReactionRuntime small(d);
    for (int step = 0; step < 5; ++step) small.step(kDt, nullptr, 0, step == 0 ? 1.0f : 0.0f, glm::vec3(0.0f), glm::vec3(0.0f), fx::Jobs(&host));
    EXPECT_GT(small.pool().alive(), 0);
    EXPECT_EQ(host.calls, 0);
}

}  // namespace
