#include "render/RenderState.h"

namespace cube {

ScopedPassState::ScopedPassState(const PassState& s) {
    if (s.depthTest) {
        glEnable(GL_DEPTH_TEST);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDepthFunc(s.depthFunc);
    glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
    if (s.cullFace) {
        glEnable(GL_CULL_FACE);
    } else {
        glDisable(GL_CULL_FACE);
    }
}

ScopedPassState::~ScopedPassState() {
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace cube
