#include "scene/cubeParticleSystem.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "platform/Trace.h"
#include "scene/WheelState.h"

namespace cube {

void cubeParticleSystem::Initialize(const LegacySmokeDesc* legacy, int pluginReaction, uint32_t seed) {
    Trace::call("cubeParticleSystem::Initialize");
    if (legacy) desc_ = *legacy;
    pluginReaction_ = pluginReaction;
    rng_ = 0x9E3779B97F4A7C15ull ^ (uint64_t(seed) << 17) ^ std::hash<std::string>{}(desc_.name);
    InitInternalParticle();
}

void cubeParticleSystem::InitInternalParticle() {
    Trace::call("cubeParticleSystem::InitInternalParticle");
    if (kind_ != Kind::Legacy) return;
    const size_t cap = size_t(std::max(desc_.capacity, 0));
    position_.reserve(cap);
    velocity_.reserve(cap);
    age_.reserve(cap);
    life_.reserve(cap);
    order_.reserve(cap);
    keys_.reserve(cap);
}

float cubeParticleSystem::random01() {
    // splitmix64: small, deterministic, good enough for sprite jitter.
    uint64_t z = (rng_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return float(z >> 40) / float(1u << 24);
}

void cubeParticleSystem::Update(float dt, const WheelState* wheels, int wheelCount) {
    if (kind_ != Kind::Legacy || !(dt > 0.0f) || !std::isfinite(dt)) return;
    // Age and retire (swap-remove keeps the arrays dense).
    for (size_t i = 0; i < age_.size();) {
        age_[i] += dt;
        if (age_[i] >= life_[i]) {
            position_[i] = position_.back(); position_.pop_back();
            velocity_[i] = velocity_.back(); velocity_.pop_back();
            age_[i] = age_.back(); age_.pop_back();
            life_[i] = life_.back(); life_.pop_back();
            continue;
        }
        // Old system: rise at a fixed speed, inherited velocity decays (exact exponential).
        const float decay = std::exp(-2.0f * dt);
        velocity_[i].x *= decay;
        velocity_[i].z *= decay;
        velocity_[i].y = desc_.riseSpeed;
        position_[i] += velocity_[i] * dt;
        ++i;
    }
    for (int w = 0; w < wheelCount; ++w) {
        const WheelState& ws = wheels[w];
        const bool wanted = desc_.wheels == "all" || (desc_.wheels == "rear") == ws.rear;
        if (!wanted || ws.slip < desc_.slipThreshold) continue;
        const float strength = std::clamp((ws.slip - desc_.slipThreshold) /
                                          std::max(1e-3f, 1.0f - desc_.slipThreshold), 0.0f, 1.0f);
        emitCarry_ += desc_.rate * strength * dt;
        while (emitCarry_ >= 1.0f) {
            emitCarry_ -= 1.0f;
            if (int(age_.size()) >= desc_.capacity) continue;
            // Spawned above the ground: the sprite's lowest corner clears it by `hover` at the
            // size it will grow to, so it can never cut into the track.
            const float r = 0.3f * random01(), a = 6.2831853f * random01();
            glm::vec3 p = ws.contact + glm::vec3(r * std::cos(a), 0.0f, r * std::sin(a));
            p.y = ws.contact.y + desc_.hover + 0.5f * std::max(desc_.startSize, desc_.endSize);
            position_.push_back(p);
            velocity_.push_back(0.2f * ws.velocity);
            age_.push_back(0.0f);
            life_.push_back(desc_.lifetime * (0.8f + 0.4f * random01()));
        }
    }
}

void cubeParticleSystem::BuildQuads(const glm::vec3& eye, const glm::vec3& right, const glm::vec3& up,
                                    std::vector<SpriteVertex>* out) const {
    out->clear();
    if (kind_ != Kind::Legacy) return;
    const size_t n = age_.size();
    order_.resize(n);
    keys_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3 d = position_[i] - eye;
        keys_[i] = glm::dot(d, d);
    }
    std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) { return keys_[a] > keys_[b]; });
    for (uint32_t i : order_) {
        const float t = age_[i] / life_[i];
        const float size = desc_.startSize + (desc_.endSize - desc_.startSize) * t;
        const float alpha = desc_.alpha * std::min(1.0f, 8.0f * t) * (1.0f - t);
        const glm::vec3 r = right * (0.5f * size), u = up * (0.5f * size), c = position_[i];
        const SpriteVertex v0{c - r - u, {0.0f, 0.0f}, alpha}, v1{c + r - u, {0.5f, 0.0f}, alpha},
            v2{c + r + u, {0.5f, 0.5f}, alpha}, v3{c - r + u, {0.0f, 0.5f}, alpha};
        out->insert(out->end(), {v0, v1, v2, v0, v2, v3});
    }
}

}  // namespace cube
