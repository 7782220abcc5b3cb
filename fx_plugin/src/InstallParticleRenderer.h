#pragma once
// Connects the particle renderer to a PluginImpl: creates a ParticleRenderer (shaders from the
// plugin's shader dir, the atlas from `dataDir`; empty = the copies embedded in the library) and installs
// the render hook that hands it every runtime's pool and reports Stats::particlesDrawn.
// fxCreatePlugin calls it once; the renderer lives as long as the hook (the plugin).
#include <string>

namespace fx {

class PluginImpl;

void installParticleRenderer(PluginImpl& plugin, const std::string& dataDir = std::string());

}  // namespace fx
