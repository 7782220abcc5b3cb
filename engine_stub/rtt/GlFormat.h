#pragma once
// GL enums for the rtt formats: the one table the pool, clears and read-backs share.
#include "gl/Gl.h"
#include "rtt/RenderTargetDesc.h"

namespace cube::rtt {

/// internalFormat / format / type as glTexImage2D wants them; attachment for depth formats.
struct GlFormat {
    GLenum internalFormat = GL_NONE;
    GLenum format = GL_NONE;
    GLenum type = GL_NONE;
    GLenum attachment = GL_NONE;  ///< depth formats: GL_DEPTH(_STENCIL)_ATTACHMENT
};

GlFormat glFormat(ColorFormat format);
GlFormat glFormat(DepthFormat format);

}  // namespace cube::rtt
