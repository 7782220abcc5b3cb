#include "fxbench_depth.h"

#include "game/Game.h"

namespace fxbench {

bool renderChaseDepth(cube::Game& game, std::vector<float>* depth, std::string* error) {
    // The engine's own frame, once more, with the chase view's scene depth read back from the
    // frame graph (its depth prepass runs for that): no second copy of the prepass.
    game.captureNextSceneDepth();
    game.RenderFrame();
    if (game.lastSceneDepth().empty()) {
        *error = "fxbench: the chase view's scene depth could not be read back";
        return false;
    }
    *depth = game.lastSceneDepth();
    return true;
}

}  // namespace fxbench
