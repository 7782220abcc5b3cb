// The immediate path: validation, the host's bindings, the frame graph and the depth hook.
#include "ImmediateRenderer.h"

#include "GlStateGuard.h"
#include "ImmediateFrame.h"
#include "PrivateGl.h"
#include "Renderers.h"
#include "ShaderLoader.h"
#include "sim/ReactionRuntime.h"

#include <string>

namespace fx {
namespace {

/// Binds `texture` to GL_TEXTURE_2D of the active unit when it is a 2D texture; false when it is
/// not a texture name (deleted, or generated and never bound) or has another target, and then no
/// GL error is left behind: glIsTexture raises none, and the one error a bind to the wrong target
/// raises is taken back at once (a context records only its first error: were the host's own
/// still pending, that one is the one taken; fx/fx.h says so).
bool bindAs2D(uint32_t texture) {
    if (!glIsTexture(texture)) return false;
    glBindTexture(GL_TEXTURE_2D, texture);
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    if (GLuint(bound) == texture) return true;
    glGetError();
    return false;
}

}  // namespace

ImmediateRenderer::ImmediateRenderer(HostAdapter* host, ProgramCache& programs)
    : host_(host), programs_(programs) {}

bool ImmediateRenderer::prepare(Diagnostics* out) {
    std::string error;
    if (!privateGlLoaded() && !(host_ && loadPrivateGl(*host_, &error))) return true;  // prepareGl reports it
    GlStateGuard guard;
    if (ensureDepthProgram()) return true;
    if (out) addShaderDiagnostics(depthError_, out);
    return false;
}

bool ImmediateRenderer::ensureDepthProgram() {
    const ProgramCache::Key key = ProgramCache::Key::of(ProgramCache::LinearizeDepth);
    if (!programs_.tried(key)) {  // a key is tried once per cache: one compile, one message
        std::vector<std::string> errors;
        programs_.build({key}, &errors);
        if (!errors.empty()) {
            depthError_ = errors.front();
            lastError_ = depthError_;
            if (host_) host_->log(LogLevel::Error, ("fx: error[ShaderBuild] immediate render: " + depthError_).c_str());
        }
    }
    return depth_.bind(programs_);
}

ImmediateRenderer::~ImmediateRenderer() { releaseGl(); }

void ImmediateRenderer::releaseGl() {
    pool_.release();
    depth_.releaseGl();
}

ErrorCode ImmediateRenderer::refuse(ErrorCode code, const std::string& what) {
    lastError_ = what;
    if (errors_) return errors_->refuse(code, "renderView", what);
    if (host_) {
        host_->log(LogLevel::Error,
                   (std::string("fx: error[") + errorCodeName(code) + "] immediate render: " + what).c_str());
    }
    return code;
}

ErrorCode ImmediateRenderer::render(Renderers& renderers, const std::vector<ReactionRuntime>& runtimes,
                                    const FrameSettings& settings, const ImmediateView& in, int* drawn) {
    using Source = ImmediateView::DepthSource;
    lastPasses_.clear();
    lastError_.clear();
    const Source source = in.depthSource;
    if (source != Source::None && source != Source::LinearR32F && source != Source::DepthTexture &&
        source != Source::BoundFramebuffer) {
        return refuse(ErrorCode::InvalidValue, "depthSource: not a DepthSource value");
    }
    if ((source == Source::LinearR32F || source == Source::DepthTexture) && in.depthTexture == 0) {
        return refuse(ErrorCode::NullArgument, "depthTexture: 0 for a depth source that needs a texture");
    }
    if (!validDepthMapping(in.view.proj, in.mapping)) {
        return refuse(ErrorCode::InvalidValue,
                      "mapping: depth range outside [0, 1] or empty, or a projection without depth");
    }
    std::string glError = "no HostAdapter to load GL through";
    if (!privateGlLoaded() && !(host_ && loadPrivateGl(*host_, &glError))) return refuse(ErrorCode::NoGlContext, glError);

    // The host's viewport places the view (anywhere in the framebuffer); with clipToHostScissor a
    // scissor it enabled clips the plugin's draws into that framebuffer too (ImmediateFrame's
    // bindForDraw); without, the host's scissor state is ignored as in 2.0.
    GLint drawFramebuffer = 0, viewport[4] = {}, scissorBox[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    const bool hostScissor = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
    GlStateGuard guard;  // the queries below bind textures and the read framebuffer
    const int vx = viewport[0], vy = viewport[1];
    // A host depth texture holds the view alone (the view's size) or the whole framebuffer with
    // the view at the viewport's origin (any other size, which must then cover the view).
    int hostTexWidth = 0, hostTexHeight = 0;
    auto placeHostTexture = [&](const char* what) -> std::string {
        glActiveTexture(GL_TEXTURE0);
        DepthLinearizer::textureSize(in.depthTexture, &hostTexWidth, &hostTexHeight);
        const bool alone = hostTexWidth == in.view.width && hostTexHeight == in.view.height;
        if (alone || (hostTexWidth >= vx + in.view.width && hostTexHeight >= vy + in.view.height)) return std::string();
        return std::string(what) + ": " + std::to_string(hostTexWidth) + "x" + std::to_string(hostTexHeight) +
               ", the view is " + std::to_string(in.view.width) + "x" + std::to_string(in.view.height) + " at (" +
               std::to_string(vx) + ", " + std::to_string(vy) +
               "); expected the view's size or a framebuffer's that holds it";
    };
    uint32_t depthFormat = 0;
    int samples = 0;
    if (source == Source::DepthTexture || source == Source::LinearR32F) {
        glActiveTexture(GL_TEXTURE0);
        if (!bindAs2D(in.depthTexture)) {
            return refuse(ErrorCode::UnsupportedDepth, "depthTexture " + std::to_string(in.depthTexture) +
                                                           ": not a GL_TEXTURE_2D (deleted, never bound, or "
                                                           "another target)");
        }
    }
    if (source == Source::LinearR32F && DepthLinearizer::textureFormat(in.depthTexture) != GL_R32F) {
        return refuse(ErrorCode::UnsupportedDepth, "depthTexture: FX_DEPTH_FROM_LINEAR reads a GL_R32F texture "
                                                   "(linear view depth in metres); this one has another format");
    }
    if (source == Source::LinearR32F) {
        const std::string bad = placeHostTexture("depthTexture");
        if (!bad.empty()) return refuse(ErrorCode::SizeMismatch, bad);
    }
    if (source == Source::DepthTexture) {
        depthFormat = supportedDepthFormat(in.depthFormat ? in.depthFormat : DepthLinearizer::textureFormat(in.depthTexture));
        const std::string bad = placeHostTexture("depthTexture");
        if (depthFormat && !bad.empty()) return refuse(ErrorCode::SizeMismatch, bad);
    } else if (source == Source::BoundFramebuffer) {
        depthFormat = DepthLinearizer::framebufferDepthFormat(uint32_t(drawFramebuffer));
        samples = DepthLinearizer::framebufferSamples(uint32_t(drawFramebuffer));
    }
    if (source == Source::DepthTexture && depthFormat == 0) {
        return refuse(ErrorCode::UnsupportedDepth,
                      "depthTexture: not a GL_DEPTH_COMPONENT16/24/32F or DEPTH24_STENCIL8 texture");
    }
    if (source == Source::BoundFramebuffer && depthFormat == 0) {
        return refuse(ErrorCode::UnsupportedDepth, "the framebuffer bound for drawing has no depth attachment "
                                                   "(give FX_DEPTH_FROM_NOTHING, or a depth texture)");
    }

    ViewInfo view = in.view;
    view.depth = conventionOf(view.proj, in.mapping);
    view.x = vx;
    view.y = vy;
    // sceneColor is the host's framebuffer, which ImmediateFrame reports at the view's size; a
    // host depth texture of the framebuffer's size is the view's target's (targetsFitView).
    const bool texAlone = hostTexWidth == view.width && hostTexHeight == view.height;
    view.targetWidth = hostTexWidth > 0 && !texAlone ? hostTexWidth : 0;
    view.targetHeight = hostTexHeight > 0 && !texAlone ? hostTexHeight : 0;
    const glm::ivec2 texelOrigin = hostTexWidth > 0 && !texAlone ? glm::ivec2(vx, vy) : glm::ivec2(0);
    const glm::ivec2 hostTexSize(hostTexWidth, hostTexHeight);

    ImmediateFrameSetup setup;
    setup.width = view.width;
    setup.height = view.height;
    setup.hostFramebuffer = uint32_t(drawFramebuffer);
    setup.viewportX = vx;
    setup.viewportY = vy;
    setup.hostScissor = hostScissor && in.view.clipToHostScissor;
    for (int i = 0; i < 4; ++i) setup.scissorBox[i] = scissorBox[i];
    if (source == Source::LinearR32F) {
        setup.hostLinearDepth = in.depthTexture;
        setup.linearWidth = hostTexWidth;
        setup.linearHeight = hostTexHeight;
    }
    const float background = view.farPlane;
    const glm::mat4 proj = view.proj;
    const DepthMapping mapping = in.mapping;
    const int w = view.width, h = view.height;
    const uint32_t hostTexture = in.depthTexture;
    setup.produceDepth = [this, source, background, proj, mapping, w, h, hostTexture, depthFormat, samples,
                          drawFramebuffer, vx, vy, texelOrigin, hostTexSize](uint32_t target, const DepthRegion& region) {
        if (!depthReady_ || source == Source::None) {
            // No depth (or no linearise program): the view's far plane everywhere, which every
            // reader takes as nothing drawn.
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
            const GLfloat far[4] = {background, 0.0f, 0.0f, 0.0f};
            glClearBufferfv(GL_COLOR, 0, far);
            return;
        }
        // The copy is the view's rectangle; the host's texture is read where the view lies in it.
        if (source == Source::DepthTexture) {
            depth_.linearize(hostTexture, proj, mapping, background, target, w, h, region, texelOrigin, hostTexSize);
            return;
        }
        const uint32_t texture = depth_.copyFramebufferDepth(uint32_t(drawFramebuffer), vx, vy, w, h, depthFormat,
                                                             samples, region);
        depth_.linearize(texture, proj, mapping, background, target, w, h, region);
    };
    // The z-buffer itself where the passes can sample it (SceneDepthSource.h): a depth texture in
    // place, the framebuffer's depth through a copy (no linearise pass); else produceDepth above.
    setup.zBuffer = source == Source::DepthTexture || source == Source::BoundFramebuffer;
    setup.zMapping.clipDepthZeroToOne = mapping.clipZeroToOne;
    setup.zMapping.depthRangeNear = mapping.rangeNear;
    setup.zMapping.depthRangeFar = mapping.rangeFar;
    if (source == Source::DepthTexture) {
        setup.hostZTexture = hostTexture;
        setup.zWidth = hostTexWidth;
        setup.zHeight = hostTexHeight;
    }
    // The bound framebuffer's depth over the view's rectangle only, into a view-sized texture.
    setup.copyZBuffer = [this, w, h, depthFormat, samples, drawFramebuffer, vx, vy](const DepthRegion& region) {
        return depth_.copyFramebufferDepth(uint32_t(drawFramebuffer), vx, vy, w, h, depthFormat, samples, region);
    };
    // What the host drew goes to the GPU before the CPU culls, sorts, bounds and bins the particles
    // (a driver may hold it until its next flush): the GPU draws the host's scene meanwhile, as a
    // frame graph's scene runs under the work its passes do (QuarterResPath::settle, TiledPath).
    // Not without a live particle: a scene without smoke costs the host no flush.
    bool anyParticle = false;
    for (const ReactionRuntime& r : runtimes) anyParticle = anyParticle || r.stateless() || r.pool().alive() > 0;
    if (anyParticle) glFlush();
    pool_.beginFrame();
    ImmediateFrame frame(pool_, std::move(setup));
    int declaredDrawn = 0;
    const ErrorCode declared = renderers.declare(view, frame, runtimes, settings, drawn ? drawn : &declaredDrawn);
    if (declared == ErrorCode::None && !frame.empty()) {
        // The linearise program: built by prepare() (prepareGl); for a host that skipped it, here,
        // before any pass (a scene without smoke compiles nothing).
        depthReady_ = source == Source::None || ensureDepthProgram();
        if (!depthReady_) lastError_ = depthError_;
        // The z-tested passes draw under the clip control and depth range the host drew its
        // z-buffer with (GlStateGuard pins them to this mapping instead of the convention's).
        HostDepthMappingScope hostMapping(in.mapping.clipZeroToOne, in.mapping.rangeNear, in.mapping.rangeFar);
        FrameScope running(FrameScope::Pass);
        frame.execute();
        lastPasses_ = frame.executed();
        lastRegion_ = frame.producedDepthRegion();
    }
    pool_.endFrame();
    return declared;
}

}  // namespace fx
