#include "fxbench_depth.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "game/Game.h"
#include "rtt/Clear.h"
#include "rtt/Readback.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace fxbench {


bool renderChaseDepth(cube::Game& game, std::vector<float>* depth, std::string* error) {
    const int w = game.chaseView().width(), h = game.chaseView().height();
    cube::rtt::RenderTargetPool& pool = game.pool();
    cube::rtt::RenderTargetDesc desc;
    desc.width = w;
    desc.height = h;
    desc.color[0] = cube::rtt::ColorFormat::R32F;
    desc.depth = cube::rtt::DepthFormat::Depth24;
    desc.filter = cube::rtt::Filter::Nearest;
    desc.name = "fxbench.depth";
    cube::rtt::RttError e = cube::rtt::RttError::None;
    const cube::rtt::RenderTargetHandle target = pool.acquire(desc, &e);
    if (!target.valid()) {
        *error = "fxbench: depth target: " + pool.lastErrorMessage();
        return false;
    }
    cube::rtt::ClearValues cv;
    cv.color[0] = {1e30f, 0.0f, 0.0f, 0.0f};
    cube::rtt::clear(pool, target, cv);
    {
        // The engine's own depth-prepass drawing (the back end), into this target.
        cube::rtt::ScopedTargetBinding bind(pool, target);
        cube::cubeScene& sc = game.scene();
        const cube::ViewCamera& cam = game.chaseView().camera();
        cube::CameraMatrices m;
        m.aspect = float(w) / float(h);
        m.fovY = cam.fovY;
        m.view = cam.view();
        m.proj = cam.proj(m.aspect);
        std::vector<cube::MeshDraw> draws;
        sc.renderer().meshes().record(sc.data(), sc.carNode(), sc.carTransform(), &draws);
        sc.renderer().depthPrepass(draws, {}, m, game.cameraQuads());
    }
    const cube::rtt::RttError re = cube::rtt::readFloat(pool, target, 0, cube::rtt::FloatLayout::Native, depth);
    pool.release(target);
    if (re != cube::rtt::RttError::None) {
        *error = "fxbench: depth read-back failed";
        return false;
    }
    return true;
}

}  // namespace fxbench
