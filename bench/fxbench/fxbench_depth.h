#pragma once
// The chase view's linear scene depth for the current simulated frame, drawn by fxbench itself
// (the engine's prepass target is transient: it lives only inside the frame graph).
#include <string>
#include <vector>

namespace cube {
class Game;
}

namespace fxbench {

/// Draws the scene (every mesh, the car where the last RenderFrame put it, and the overdraw
/// panels) with the engine's depth-prepass program into a width x height R32F + depth target
/// from the game's pool, reads it back (metres, rows top-down; 1e30 where nothing was drawn)
/// and releases the target. Call after a RenderFrame of the same simulated frame. GL state is
/// restored. False + error when the target cannot be made.
bool renderChaseDepth(cube::Game& game, std::vector<float>* depth, std::string* error);

}  // namespace fxbench
