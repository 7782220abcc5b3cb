#pragma once
// CUBE's Render component. Render::Dyn handles the developer keys, then renders the scene: the
// frame is rebuilt as a list of declared passes every frame, compiled (culling what nobody
// reads) and executed.
#include <map>
#include <string>
#include <vector>

#include "gl/Image.h"

namespace cube {

class Game;

/// What a frame writes back into the game beyond what Game's public interface offers: the
/// read-backs the game asked for and the pass counters. Game fills it from its own members, so
/// Render reaches the rest only through that public interface.
struct RenderFrameOutputs {
    ImageRGBA8* frame = nullptr;               ///< non-null: the presented frame is read back into it
    std::vector<float>* sceneDepth = nullptr;  ///< non-null: the chase view's linear depth (metres)
    std::map<std::string, int>* passRuns = nullptr;   ///< +1 per pass executed
    std::map<std::string, int>* passCulls = nullptr;  ///< +1 per pass culled
};

class Render {
public:
    /// False when the window is minimised: nothing drawn and nothing read back (the requests in
    /// `out` stay the game's to make again).
    bool Dyn(Game& game, const RenderFrameOutputs& out);

private:
    void handleKeys(Game& game);
};

}  // namespace cube
