#include "FxTestHost.h"

namespace fxtest {

DirectParticles::DirectParticles(fx::HostAdapter* host, std::string shaderDir, std::string dataDir,
                                 int capacity)
    : desc(fx::defaultReaction(fx::ReactionType::WheelSmoke)),
      programs(fx::snapshotShaderReader(fx::shaderReader(shaderDir))),
      renderer(fx::RendererConfig{host, std::move(shaderDir), std::move(dataDir), nullptr, fx::Jobs(host)}, programs),
      pool(capacity) {
    desc.name = "hand_placed";
    desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f)}};
}

void buildLinearizeProgram(fx::ProgramCache* programs) {
    std::vector<std::string> errors;
    programs->build({fx::ProgramCache::Key::of(fx::ProgramCache::LinearizeDepth)}, &errors);
    EXPECT_TRUE(errors.empty()) << errors.front();
}

void DirectParticles::setMode(const RenderMode& m) {
    settings.options.techniqueOverride = m.technique;
    settings.options.quarterRes = m.quarter;
    settings.options.quarterResAlways = m.quarter;
    settings.options.tiled = false;
    settings.options.tiling = m.tiled ? fx::Tiling::On : fx::Tiling::Off;  // the mode's path on any context
}

void DirectParticles::set(const std::vector<HandParticle>& particles) {
    pool.clear();
    for (const HandParticle& p : particles) {
        const int i = pool.spawn();
        if (i < 0) break;
        pool.stream(fx::ParticlePool::PosX)[i] = p.position.x;
        pool.stream(fx::ParticlePool::PosY)[i] = p.position.y;
        pool.stream(fx::ParticlePool::PosZ)[i] = p.position.z;
        pool.stream(fx::ParticlePool::VelX)[i] = 0.0f;
        pool.stream(fx::ParticlePool::VelY)[i] = 0.0f;
        pool.stream(fx::ParticlePool::VelZ)[i] = 0.0f;
        pool.stream(fx::ParticlePool::Age)[i] = p.life;
        pool.stream(fx::ParticlePool::Lifetime)[i] = 1.0f;
        pool.stream(fx::ParticlePool::StartSize)[i] = p.size;
        pool.stream(fx::ParticlePool::EndSize)[i] = p.size;
        pool.stream(fx::ParticlePool::Rotation)[i] = p.rotation;
        pool.stream(fx::ParticlePool::Spin)[i] = 0.0f;
        pool.stream(fx::ParticlePool::Size)[i] = p.size;
        pool.stream(fx::ParticlePool::Life)[i] = p.life;
        pool.stream(fx::ParticlePool::Fade)[i] = p.fade;
        pool.frame()[i] = uint8_t(p.frame);
    }
}

int DirectParticles::declare(const fx::ViewInfo& view, fx::FrameBuilder& frame) {
    fx::ParticleBatch batch;
    batch.pool = &pool;
    batch.desc = &desc;
    batch.sortBackToFront = desc.render.sortBackToFront && desc.render.blend != fx::BlendMode::Additive;
    return renderer.declarePasses(view, frame, &batch, 1, settings);
}

}  // namespace fxtest
