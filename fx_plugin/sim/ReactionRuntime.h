#pragma once
// One loaded reaction while the game runs: its description, its particle pool (allocated once,
// here), the emission carry of each wheel and its random generator. step() is
// Reaction::Continue for every type (wheel smoke, dust, collision burst).
//
// Per-type behaviour (the "continue"):
//  - wheel_smoke: each wheel in trigger.wheels that is grounded, on a listed surface, at
//    >= min_speed and at slip >= slip_threshold emits rate * s particles/s with
//    s = clamp((slip - threshold) / (1 - threshold), 0, 1): none at the threshold, full rate at
//    slip 1 (and beyond);
//  - dust: same gates, strength s = clamp((speed - min_speed) / kDustFullRateSpan, 0, 1), speed
//    = |hub velocity|, so dust thickens with speed up to full rate 15 m/s above min_speed;
//  - collision_burst: when the collision amount rises to >= collision_threshold (and > 0) it
//    emits max(1, round(burst * min(amount, 1))) particles at once at the collision point; it
//    fires again only after the amount fell to <= threshold / 2 (edge-triggered, with hysteresis
//    so a noisy contact does not machine-gun).
//  - collision_scrape: while the collision amount is >= collision_threshold (and > 0) it emits
//    rate * min(amount, 1) particles/s at the collision point (sparks while the car grinds
//    along a barrier), nothing otherwise.
//  - on_demand: emits `burst` particles at once at the point given to fire(), at the next step
//    (an explosion the host sets off: a key, a script).
// Spawn point = contact + spawn_height * up + a point uniform in a horizontal disc of
// jitter_radius. A particle that fell due `a` seconds before the end of the step starts where
// the wheel was then (contact - hub velocity * a) and is advanced by `a` exactly, so a trail is
// continuous at any frame rate. Initial velocity = inherit_velocity * hub velocity + a random
// spread_speed in the upper hemisphere.
//
// Turbulence and vortex (sim/CurlNoise.h) add an air velocity that depends on the particle's
// place and the reaction's clock: u(x, t) = terminal + turbulence(x, t) + vortex(x - origin).
// The step stays the exact drag solution for a constant u, taken with u sampled at the midpoint
// of the step (an exponential midpoint rule): unconditionally stable for any drag * dt, since the
// drag part is still exact and u is bounded, and second order in dt in the field's variation, so
// 30 Hz and 300 Hz runs agree within the error fxbench --integrators reports. Reactions without
// turbulence or vortex take the exact constant-u step as before (no extra cost).
//
// technique: stateless: spawn() writes a birth record (position and velocity at birth, before any
// ageing, and the birth time on the reaction clock) into a ring instead of the pool, and step()
// touches no particle: the vertex shader evaluates each record at the current time. The random
// draws are the same as for a CPU technique, so the same desc gives the same particles either way
// (tested: the closed form equals the CPU steps over the whole life). The pool is empty.
//
// Gravity (particle.gravity, downward) enters both paths as a constant acceleration in the exact
// step (Integrator.h: applyDragStep with g).
//
// Nothing here allocates after construction; a full pool drops what does not fit and counts it.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "EmissionClock.h"
#include "Integrator.h"
#include "ParticlePool.h"
#include "base/ParallelFor.h"
#include "Rng.h"
#include "StatelessRing.h"
#include "reactions/ReactionDesc.h"
#include "fx/Types.h"

namespace fx {

class ReactionRuntime {
public:
    static constexpr int kMaxWheels = 16;            ///< wheels past this are ignored
    static constexpr float kDustFullRateSpan = 15.0f;  ///< m/s above min_speed for full dust
    static constexpr uint64_t kDefaultSeed = 0x5EEDC0DEull;

    struct Counters {
        uint64_t emitted = 0;  ///< particles that went into the pool
        uint64_t dropped = 0;  ///< particles due while the pool was full
        uint64_t bursts = 0;   ///< collision bursts fired
    };

    /// Allocates the pool (desc.emission.capacity, validated by the loader) and seeds the
    /// generator from `globalSeed` and the reaction's name.
    explicit ReactionRuntime(ReactionDesc desc, uint64_t globalSeed = kDefaultSeed);

    /// Advances every particle by dt and emits for this step. dt <= 0, NaN or Inf: no-op.
    /// `wheels` may be null when wheelCount is 0. Non-finite inputs are ignored, not propagated.
    /// `jobs`: the host's job system; a pool of tens of thousands is advanced in pieces on it,
    /// to the same state bit for bit (the same particles in the same slots).
    void step(float dt, const WheelContact* wheels, int wheelCount, float collisionAmount,
              glm::vec3 collisionPoint, glm::vec3 wind, const Jobs& jobs = Jobs());

    /// Hot reload of a reaction whose name and capacity did not change: new parameters, same
    /// particles, carries and generator (the smoke on screen stays).
    void setDesc(ReactionDesc desc);

    const ReactionDesc& desc() const { return desc_; }
    const std::string& name() const { return desc_.name; }
    const ParticlePool& pool() const { return pool_; }
    /// technique stateless: the birth records (empty ring otherwise).
    const StatelessRing& ring() const { return ring_; }
    bool stateless() const { return desc_.render.stateless; }
    /// Live particles: the pool's, or the ring's records alive now (O(capacity) when stateless).
    int alive() const { return stateless() ? ring_.alive(time_) : pool_.alive(); }
    /// Particle slots: pool or ring.
    int capacity() const { return stateless() ? ring_.capacity() : pool_.capacity(); }
    const Counters& counters() const { return counters_; }
    /// Whether draw order matters: render.sort_back_to_front and a blend that is not additive.
    bool needsSorting() const;
    /// The terminal velocity of the last step (wind * wind_factor + rise_speed * up): what a
    /// stateless particle's closed form uses (it assumes the wind constant since its birth).
    glm::vec3 terminal() const { return terminal_; }
    /// Seconds simulated so far (the turbulence field's clock).
    double time() const { return time_; }
    /// Whether particles feel turbulence or the vortex (the midpoint step).
    bool turbulent() const { return desc_.turbulence.enabled() || desc_.vortex.enabled(); }
    /// Air velocity at x and time t for a particle born at `origin`: terminal + turbulence + vortex.
    glm::vec3 airVelocity(glm::vec3 terminal, glm::vec3 x, glm::vec3 origin, double t) const;
    /// Advances one particle by dt from time t through the field (the exponential midpoint step).
    void stepThroughField(glm::vec3& x, glm::vec3& v, glm::vec3 origin, glm::vec3 terminal,
                          double t, float dt) const;
    /// The same with the drag coefficients of dt / 2 and dt precomputed (one pair per frame).
    void stepThroughField(glm::vec3& x, glm::vec3& v, glm::vec3 origin, glm::vec3 terminal,
                          double t, const DragStep& half, const DragStep& full) const;

    /// on_demand: emits the burst at `point` in the next step (a second call before it moves it).
    void fire(glm::vec3 point) {
        firePending_ = true;
        firePoint_ = point;
    }

    /// Emission strength in [0, 1] of one wheel for this reaction (0 = the trigger is not met).
    static float wheelStrength(const ReactionDesc& desc, const WheelContact& wheel);

private:
    void advanceParticles(float dt, glm::vec3 terminal, const Jobs& jobs);
    void emitFromWheel(int index, const WheelContact& wheel, float dt, glm::vec3 terminal);
    void emitBurst(float amount, glm::vec3 point, glm::vec3 terminal);
    void emitScrape(float dt, float amount, glm::vec3 point, glm::vec3 terminal);
    /// Draws one particle's randoms and, unless it is already dead at `age`, puts it in the
    /// pool at `origin` (+ jitter) with `baseVelocity` (+ spread), advanced by `age` seconds.
    void spawn(glm::vec3 origin, glm::vec3 baseVelocity, float age, glm::vec3 terminal);

    ReactionDesc desc_;
    ParticlePool pool_;
    std::vector<uint8_t> dead_;  // scratch of a step in pieces: slot i's particle reached its lifetime
    StatelessRing ring_;
    Pcg32 rng_;
    std::array<EmissionClock, kMaxWheels> clocks_{};
    bool burstArmed_ = true;
    double time_ = 0.0;
    bool firePending_ = false;
    glm::vec3 firePoint_{0.0f};
    glm::vec3 terminal_{0.0f};
    Counters counters_;
};

}  // namespace fx
