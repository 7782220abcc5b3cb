#pragma once
// Everything the plugin's switches say about how this frame's particles are drawn: PluginImpl's
// setters write its one copy, and each drawing call hands it to every rendering path by value.
// No path reads a switch anywhere else, so a frame is drawn under one set of settings even when
// a setter is called while its passes are pending.
#include "LightState.h"
#include "fx/Plugin.h"

namespace fx {

struct FrameSettings {
    RenderOptions options;  ///< technique override, quarter res, bilinear upsample (setRenderOptions)
    ParticleShape shape = ParticleShape::Trimmed;  ///< trimmed polygons or full quads
    LightState light;  ///< the scene light (LightState::on false: unlit)
};

}  // namespace fx
