#include "fxbench_depth.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "fxbench_gl.h"
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
        cube::rtt::ScopedTargetBinding bind(pool, target);
        GlStateGuard guard;
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glEnable(GL_CULL_FACE);
        cube::cubeScene& sc = game.scene();
        const cube::ViewCamera& cam = game.chaseView().camera();
        const float aspect = float(w) / float(h);
        const glm::mat4 view = cam.view(), proj = cam.proj(aspect);
        const cube::gl::Program& p = sc.prepassProgram;
        glUseProgram(p.id());
        glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
        glUniformMatrix4fv(p.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(proj));
        std::vector<cube::MeshDraw> draws;
        sc.gpu().record(sc.data(), sc.carNode(), sc.carTransform(), &draws);
        sc.gpu().draw(draws, p.uniform("uModel"), -1);
        sc.drawOverdrawPanels(p, game.options().overdrawLayers, view, cam.fovY, aspect);
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
