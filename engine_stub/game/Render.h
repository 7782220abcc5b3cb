#pragma once
// CUBE's Render component. Render::Dyn handles the developer keys, then renders the scene: the
// frame is rebuilt as a list of declared passes every frame, compiled (culling what nobody
// reads) and executed.
namespace cube {

class Game;

class Render {
public:
    void Dyn(Game& game);

private:
    void handleKeys(Game& game);
};

}  // namespace cube
