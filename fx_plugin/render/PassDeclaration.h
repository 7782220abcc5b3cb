#pragma once
// What the billboard paths (FullResPath, QuarterResPath) do alike while declaring their passes:
// a pass that reads only the valid ones of its targets, the scene depth region the immediate path
// must linearise for them, and the footprint their screen bound is taken with.
#include <functional>
#include <initializer_list>

#include "DrawList.h"
#include "ScreenTiles.h"
#include "fx/HostAdapter.h"

namespace fx {

/// FrameBuilder::addPass with the valid ones of up to four read targets (an invalid Target is
/// "not read": the opacity map is there only for lit smoke).
void addPassReading(FrameBuilder& frame, const char* name, std::initializer_list<Target> maybeReads, Target write,
                    std::function<void(PassContext&)> execute);

/// The immediate path (ImmediateFrame) copies and linearises the host's z-buffer only where the
/// plugin's passes read it: tells it the region the next pass reads, `bound` grown by the
/// quarter-res tiles' reach and aligned to 64 px blocks. Other frame
/// builders read the whole depth anyway: nothing to say to them.
void narrowDepthRead(FrameBuilder& frame, const ScreenRect& bound, int width, int height);

/// Box when a visible batch is drawn as spheres, else Billboard (ScreenTiles.h).
Footprint footprintOf(const DrawList& list);

}  // namespace fx
