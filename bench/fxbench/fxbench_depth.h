#pragma once
// The chase view's linear scene depth for the current simulated frame, read back from the
// engine's own frame (Game::captureNextSceneDepth).
#include <string>
#include <vector>

namespace cube {
class Game;
}

namespace fxbench {

/// Renders the current simulated frame once more (in the mode last applied) with the chase
/// view's scene depth read back: metres, rows top-down, 1e30 where nothing was drawn. Call after
/// a RenderFrame of the same simulated frame. False + error when the read-back failed.
bool renderChaseDepth(cube::Game& game, std::vector<float>* depth, std::string* error);

}  // namespace fxbench
