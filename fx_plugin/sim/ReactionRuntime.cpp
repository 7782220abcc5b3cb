#include "ReactionRuntime.h"

#include <cassert>
#include <cmath>
#include <utility>

#include "CurlNoise.h"
#include "Integrator.h"
#include "Lifecycle.h"

namespace fx {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kTwoPi = 6.28318530717959f;

bool finite3(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float wrapAngle(float a) {
    if (a > kPi || a < -kPi) a = std::remainder(a, kTwoPi);
    return a;
}

bool wheelSelected(WheelSet set, const WheelContact& w) {
    switch (set) {
    case WheelSet::Rear: return w.rear;
    case WheelSet::Front: return !w.rear;
    case WheelSet::All: return true;
    }
    return false;
}

}  // namespace

ReactionRuntime::ReactionRuntime(ReactionDesc desc, uint64_t globalSeed)
    : desc_(std::move(desc)),
      pool_(desc_.render.stateless ? 0 : desc_.emission.capacity),
      ring_(desc_.render.stateless ? desc_.emission.capacity : 0),
      rng_(reactionRng(globalSeed, desc_.name)) {}

void ReactionRuntime::setDesc(ReactionDesc desc) {
    assert(desc.emission.capacity == desc_.emission.capacity);
    assert(desc.render.stateless == stateless());
    if (desc.type != desc_.type) burstArmed_ = true;
    desc_ = std::move(desc);
}

bool ReactionRuntime::needsSorting() const {
    return desc_.render.sortBackToFront && desc_.render.blend != BlendMode::Additive;
}

float ReactionRuntime::wheelStrength(const ReactionDesc& desc, const WheelContact& w) {
    const TriggerDesc& t = desc.trigger;
    if (desc.type == ReactionType::CollisionBurst || desc.type == ReactionType::CollisionScrape ||
        desc.type == ReactionType::OnDemand || !w.grounded) {
        return 0.0f;
    }
    if (!wheelSelected(t.wheels, w)) return 0.0f;
    if (w.surface >= Surface::Count || !(t.surfaces & surfaceBit(w.surface))) return 0.0f;
    const float speed = glm::length(w.velocity);
    if (!std::isfinite(speed) || speed < t.minSpeed) return 0.0f;
    if (!(w.slip >= t.slipThreshold)) return 0.0f;  // also rejects NaN slip
    if (desc.type == ReactionType::WheelSmoke) {
        if (t.slipThreshold >= 1.0f) return 1.0f;
        return glm::clamp((w.slip - t.slipThreshold) / (1.0f - t.slipThreshold), 0.0f, 1.0f);
    }
    return glm::clamp((speed - t.minSpeed) / kDustFullRateSpan, 0.0f, 1.0f);
}

void ReactionRuntime::step(float dt, const WheelContact* wheels, int wheelCount,
                           float collisionAmount, glm::vec3 collisionPoint, glm::vec3 wind, const Jobs& jobs) {
    dt = sanitizeDt(dt);
    if (dt == 0.0f) return;
    if (!finite3(wind)) wind = glm::vec3(0.0f);
    const ParticleDesc& p = desc_.particle;
    const glm::vec3 terminal = terminalVelocity(wind, p.windFactor, p.riseSpeed);
    terminal_ = terminal;

    if (!stateless()) advanceParticles(dt, terminal, jobs);  // stateless: nothing to update
    time_ += dt;

    if (desc_.type == ReactionType::OnDemand) {
        if (firePending_) {
            firePending_ = false;
            ++counters_.bursts;
            for (int k = 0; k < desc_.emission.burst; ++k) {
                if (!stateless() && pool_.full()) {
                    counters_.dropped += static_cast<uint64_t>(desc_.emission.burst - k);
                    break;
                }
                spawn(firePoint_, glm::vec3(0.0f), 0.0f, terminal);
            }
        }
        return;
    }
    if (desc_.type == ReactionType::CollisionScrape) {
        emitScrape(dt, collisionAmount, collisionPoint, terminal);
        return;
    }
    if (desc_.type == ReactionType::CollisionBurst) {
        emitBurst(collisionAmount, collisionPoint, terminal);
        return;
    }
    const int n = wheels ? glm::min(wheelCount, kMaxWheels) : 0;
    for (int i = 0; i < n; ++i) emitFromWheel(i, wheels[i], dt, terminal);
}

glm::vec3 ReactionRuntime::airVelocity(glm::vec3 terminal, glm::vec3 x, glm::vec3 origin,
                                       double t) const {
    return terminal + curlNoise(desc_.turbulence, x, t) + vortexVelocity(desc_.vortex, x, origin);
}

void ReactionRuntime::stepThroughField(glm::vec3& x, glm::vec3& v, glm::vec3 origin,
                                       glm::vec3 terminal, double t, float dt) const {
    const float k = desc_.particle.drag;
    stepThroughField(x, v, origin, terminal, t, makeDragStep(k, 0.5f * dt), makeDragStep(k, dt));
}

void ReactionRuntime::stepThroughField(glm::vec3& x, glm::vec3& v, glm::vec3 origin,
                                       glm::vec3 terminal, double t, const DragStep& half,
                                       const DragStep& full) const {
    // Predictor: half a step in the air at the start; corrector: the whole step in the air at
    // the predicted midpoint. Both are the exact drag solution for their constant u.
    glm::vec3 xh = x, vh = v;
    if (full.dt == 0.0f) return;
    const glm::vec3 g(0.0f, -desc_.particle.gravity, 0.0f);
    applyDragStep(half, airVelocity(terminal, x, origin, t), g, xh, vh);
    const glm::vec3 um = airVelocity(terminal, xh, origin, t + 0.5 * static_cast<double>(full.dt));
    applyDragStep(full, um, g, x, v);
}

void ReactionRuntime::advanceParticles(float dt, glm::vec3 u, const Jobs& jobs) {
    const ParticleDesc& p = desc_.particle;
    const DragStep s = makeDragStep(p.drag, dt);
    float* px = pool_.stream(ParticlePool::PosX);
    float* py = pool_.stream(ParticlePool::PosY);
    float* pz = pool_.stream(ParticlePool::PosZ);
    float* vx = pool_.stream(ParticlePool::VelX);
    float* vy = pool_.stream(ParticlePool::VelY);
    float* vz = pool_.stream(ParticlePool::VelZ);
    float* age = pool_.stream(ParticlePool::Age);
    const float* lifetime = pool_.stream(ParticlePool::Lifetime);
    const float* start = pool_.stream(ParticlePool::StartSize);
    const float* end = pool_.stream(ParticlePool::EndSize);
    float* rot = pool_.stream(ParticlePool::Rotation);
    const float* spin = pool_.stream(ParticlePool::Spin);
    float* size = pool_.stream(ParticlePool::Size);
    float* life = pool_.stream(ParticlePool::Life);
    float* fade = pool_.stream(ParticlePool::Fade);
    const float* ox = pool_.stream(ParticlePool::OriginX);
    const float* oz = pool_.stream(ParticlePool::OriginZ);
    const bool field = turbulent();
    const float gy = -p.gravity;
    const DragStep half = field ? makeDragStep(p.drag, 0.5f * dt) : DragStep{};

    // One particle's step; false when it has reached its lifetime (and is left as it is). It
    // reads and writes slot i alone, so where in the pool (or on which thread) it runs changes
    // nothing. Captured by value, and copied into the pieces' task: the loop below keeps the
    // stream pointers in registers across the pool's kill().
    const ParticleDesc* desc = &p;  // captured as a pointer: [=] would copy the desc (its curves)
    const auto advance = [this, desc, dt, u, s, half, field, gy, px, py, pz, vx, vy, vz, age, lifetime, start, end, rot,
                          spin, size, life, fade, ox, oz](int i) {
        age[i] += dt;
        if (age[i] >= lifetime[i]) return false;
        if (field) {
            glm::vec3 x(px[i], py[i], pz[i]), v(vx[i], vy[i], vz[i]);
            stepThroughField(x, v, glm::vec3(ox[i], 0.0f, oz[i]), u, time_, half, s);
            px[i] = x.x, py[i] = x.y, pz[i] = x.z;
            vx[i] = v.x, vy[i] = v.y, vz[i] = v.z;
        } else {
            const float dx = vx[i] - u.x, dy = vy[i] - u.y, dz = vz[i] - u.z;
            px[i] += u.x * s.dt + dx * s.reach;
            py[i] += u.y * s.dt + dy * s.reach + gy * s.lift;
            pz[i] += u.z * s.dt + dz * s.reach;
            vx[i] = u.x + dx * s.decay;
            vy[i] = u.y + dy * s.decay + gy * s.reach;
            vz[i] = u.z + dz * s.decay;
        }
        rot[i] = wrapAngle(rot[i] + spin[i] * dt);
        const float f = age[i] / lifetime[i];
        life[i] = f;
        size[i] = sizeAt(*desc, start[i], end[i], f);
        fade[i] = fadeAt(*desc, f);
        return true;
    };

    const int n = pool_.alive();
    const Pieces pieces = splitWork(size_t(n), 8192, HostAdapter::kMaxTasks);
    if (!jobs.parallel() || pieces.count <= 1) {
        for (int i = 0; i < pool_.alive();) {
            if (advance(i)) {
                ++i;
            } else {
                pool_.kill(i);  // slot i now holds the last particle, not yet advanced: revisit i
            }
        }
        return;
    }
    // In pieces: every particle advanced where it lies, the dead marked; then the dead leave as
    // the loop above lets them (the last particle takes a dead one's slot, and is looked at
    // there again), so the pool ends the same, slot for slot. The one moved was advanced in its
    // old slot, which gives what advancing it in the new one gives.
    if (dead_.size() < size_t(n)) dead_.resize(size_t(pool_.capacity()));
    std::array<uint32_t, HostAdapter::kMaxTasks> deaths{};
    jobs.run(pieces, [&, advance](uint32_t piece) {
        uint32_t died = 0;
        for (size_t i = pieces.begin(piece), e = pieces.end(piece); i < e; ++i) {
            const bool lives = advance(int(i));
            dead_[i] = lives ? 0 : 1;
            died += lives ? 0u : 1u;
        }
        deaths[piece] = died;
    });
    uint32_t died = 0;
    for (uint32_t piece = 0; piece < pieces.count; ++piece) died += deaths[piece];
    for (int i = 0; died > 0 && i < pool_.alive();) {
        if (!dead_[size_t(i)]) {
            ++i;
            continue;
        }
        dead_[size_t(i)] = dead_[size_t(pool_.alive() - 1)];
        pool_.kill(i);
        --died;  // each kill takes one dead particle out: none left, nothing more to look at
    }
}

void ReactionRuntime::emitFromWheel(int index, const WheelContact& wheel, float dt,
                                    glm::vec3 terminal) {
    if (!finite3(wheel.position) || !finite3(wheel.velocity)) return;
    const float strength = wheelStrength(desc_, wheel);
    EmissionClock& clock = clocks_[static_cast<size_t>(index)];
    const int64_t due = clock.advance(static_cast<double>(desc_.emission.rate) * strength, dt);
    if (due <= 0) return;
    const glm::vec3 base = wheel.velocity * desc_.particle.inheritVelocity;
    for (int64_t k = clock.firstYoungerThan(desc_.particle.lifetimeMax); k < due; ++k) {
        if (!stateless() && pool_.full()) {
            counters_.dropped += static_cast<uint64_t>(due - k);
            return;
        }
        const float age = static_cast<float>(clock.ageOf(k));
        spawn(wheel.position - wheel.velocity * age, base, age, terminal);
    }
}

void ReactionRuntime::emitScrape(float dt, float amount, glm::vec3 point, glm::vec3 terminal) {
    if (!std::isfinite(amount) || !finite3(point)) amount = 0.0f;
    // Only while in contact: at or above the threshold (and above 0), at rate x amount.
    const bool contact = amount > 0.0f && amount >= desc_.trigger.collisionThreshold;
    EmissionClock& clock = clocks_[0];
    const double rate = contact ? static_cast<double>(desc_.emission.rate) * glm::min(amount, 1.0f) : 0.0;
    const int64_t due = clock.advance(rate, dt);
    if (!contact) clock.reset();  // no carry across contacts: a new scrape starts clean
    for (int64_t k = clock.firstYoungerThan(desc_.particle.lifetimeMax); k < due; ++k) {
        if (!stateless() && pool_.full()) {
            counters_.dropped += static_cast<uint64_t>(due - k);
            return;
        }
        spawn(point, glm::vec3(0.0f), static_cast<float>(clock.ageOf(k)), terminal);
    }
}

void ReactionRuntime::emitBurst(float amount, glm::vec3 point, glm::vec3 terminal) {
    if (!std::isfinite(amount)) amount = 0.0f;
    const float threshold = desc_.trigger.collisionThreshold;
    if (!burstArmed_) {
        if (amount <= 0.5f * threshold) burstArmed_ = true;
        return;
    }
    if (amount <= 0.0f || amount < threshold || !finite3(point)) return;
    burstArmed_ = false;
    ++counters_.bursts;
    const float scaled = static_cast<float>(desc_.emission.burst) * glm::min(amount, 1.0f);
    const int count = glm::max(1, static_cast<int>(std::lround(scaled)));
    for (int k = 0; k < count; ++k) {
        if (!stateless() && pool_.full()) {
            counters_.dropped += static_cast<uint64_t>(count - k);
            return;
        }
        spawn(point, glm::vec3(0.0f), 0.0f, terminal);
    }
}

void ReactionRuntime::spawn(glm::vec3 origin, glm::vec3 baseVelocity, float age,
                            glm::vec3 terminal) {
    const ParticleDesc& p = desc_.particle;
    const EmissionDesc& e = desc_.emission;
    // Every random draw happens whether or not the particle survives, so the sequence of
    // draws (and so every later particle) does not depend on which ones were dead on arrival.
    const float lifetime = rng_.uniform(p.lifetimeMin, p.lifetimeMax);
    const float jr = e.jitterRadius * std::sqrt(rng_.uniform());
    const float ja = kTwoPi * rng_.uniform();
    const float cosUp = rng_.uniform();  // uniform over the upper hemisphere
    const float azimuth = kTwoPi * rng_.uniform();
    const float speed = p.spreadSpeed * rng_.uniform();
    const float sizeScale = 1.0f + p.sizeVariation * (2.0f * rng_.uniform() - 1.0f);
    const float rotation = rng_.uniform(-kPi, kPi);
    const float spin = rng_.uniform(p.spinMin, p.spinMax);
    const uint32_t frame = static_cast<uint32_t>(p.atlasFirst) +
                           rng_.below(static_cast<uint32_t>(glm::max(p.atlasCount, 1)));
    if (!(age < lifetime)) return;
    const float sinUp = std::sqrt(glm::max(0.0f, 1.0f - cosUp * cosUp));
    glm::vec3 x = origin + glm::vec3(jr * std::cos(ja), e.spawnHeight, jr * std::sin(ja));
    glm::vec3 v = baseVelocity +
                  speed * glm::vec3(sinUp * std::cos(azimuth), cosUp, sinUp * std::sin(azimuth));
    if (stateless()) {
        StatelessRecord r{};
        r.p0[0] = x.x, r.p0[1] = x.y, r.p0[2] = x.z;
        r.v0[0] = v.x, r.v0[1] = v.y, r.v0[2] = v.z;
        r.birth = static_cast<float>(time_ - static_cast<double>(age));
        r.lifetime = lifetime;
        r.startSize = p.startSize * sizeScale;
        r.endSize = p.endSize * sizeScale;
        r.rotation = rotation;
        r.spin = spin;
        r.frame = static_cast<float>(frame);
        ++counters_.emitted;
        if (!ring_.write(r, time_)) ++counters_.dropped;  // a live one recycled early: ring too small
        return;
    }
    const int i = pool_.spawn();
    if (i < 0) {
        ++counters_.dropped;
        return;
    }
    ++counters_.emitted;

    if (age > 0.0f) {
        // time_ is already the end of this step: the particle was born `age` seconds before it.
        if (turbulent()) {
            stepThroughField(x, v, origin, terminal, time_ - age, age);
        } else {
            applyDragStep(makeDragStep(p.drag, age), terminal, glm::vec3(0.0f, -p.gravity, 0.0f), x, v);
        }
    }

    pool_.stream(ParticlePool::PosX)[i] = x.x;
    pool_.stream(ParticlePool::PosY)[i] = x.y;
    pool_.stream(ParticlePool::PosZ)[i] = x.z;
    pool_.stream(ParticlePool::VelX)[i] = v.x;
    pool_.stream(ParticlePool::VelY)[i] = v.y;
    pool_.stream(ParticlePool::VelZ)[i] = v.z;
    pool_.stream(ParticlePool::Age)[i] = age;
    pool_.stream(ParticlePool::Lifetime)[i] = lifetime;
    pool_.stream(ParticlePool::StartSize)[i] = p.startSize * sizeScale;
    pool_.stream(ParticlePool::EndSize)[i] = p.endSize * sizeScale;
    pool_.stream(ParticlePool::Rotation)[i] = wrapAngle(rotation + spin * age);
    pool_.stream(ParticlePool::Spin)[i] = spin;
    const float f = age / lifetime;
    pool_.stream(ParticlePool::Life)[i] = f;
    pool_.stream(ParticlePool::Size)[i] = sizeAt(p, p.startSize * sizeScale, p.endSize * sizeScale, f);
    pool_.stream(ParticlePool::Fade)[i] = fadeAt(p, f);
    pool_.stream(ParticlePool::OriginX)[i] = origin.x;
    pool_.stream(ParticlePool::OriginZ)[i] = origin.z;
    pool_.frame()[i] = static_cast<uint8_t>(frame);
}

}  // namespace fx
