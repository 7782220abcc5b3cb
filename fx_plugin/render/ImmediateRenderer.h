#pragma once
// The immediate path: for an engine without a frame graph. One call per view
// draws the plugin's passes into the framebuffer bound for drawing at the call; the plugin brings
// its own frame graph (ImmediateFrame), its own render targets (ImmediateTargetPool, kept across
// frames) and, when the host has no linear depth, its own linear depth from the host's z-buffer
// (DepthLinearizer). The C API (API 2.0) calls this; a C++ host may too.
//
// The call's contract:
//   - the host's GL context is current; GL_DRAW_FRAMEBUFFER is the framebuffer to draw into (0 =
//     the default one), with the host's z-buffer attached for the z-tested passes; the viewport's
//     origin is the view's lower-left corner, anywhere in the framebuffer, its size the view's
//     (ViewInfo::width x height); with ViewInfo::clipToHostScissor a scissor test the host
//     enabled clips the plugin's draws into that framebuffer too (else it is ignored, as in 2.0);
//   - ImmediateView::mapping states the clip control and depth range the host drew its z-buffer
//     with; the z-tested passes draw under exactly those (GlStateGuard pins them through a
//     HostDepthMappingScope), whatever the host left current, so with the view's proj the
//     plugin's clip z lands where the host's did;
//   - the z-tested passes compare in the direction conventionOf(proj, mapping) gives: the
//     ViewInfo::depth handed to the plugin is replaced by it;
//   - after the call every GL state GlStateGuard captures, the bound framebuffers and the viewport
//     included, is what it was.
//   - the scene depth is addressed by the view's own pixels (SceneDepthSource.h): the copy of a
//     bound framebuffer's depth is the view's rectangle; a host texture of the view's size holds
//     the view alone, one of another size the whole framebuffer with the view at the viewport's
//     origin (it must cover the view, else SizeMismatch).
//
// How close its images come to the frame-graph path's is measured in
// tests/fx_host/ImmediateRendererTest.cpp, what the depth source costs in ImmediateFrameTest.cpp;
// the figures are in docs/results.md (session 12).
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Plugin.h"
#include "DepthMapping.h"
#include "DepthLinearizer.h"
#include "ImmediateTargetPool.h"
#include "../base/ApiErrors.h"

namespace fx {

class Renderers;
class ReactionRuntime;
struct FrameSettings;

/// One view for ImmediateRenderer::render. Right-handed (the C layer converts left-handed hosts).
/// Defaults: no depth (soft and spherical particles then fade against nothing), GL's depth mapping.
struct ImmediateView {
    ViewInfo view;  ///< matrices, near/far, size (fx/Types.h)
    /// Where the scene depth comes from:
    ///   None             no depth: passes that read it see "nothing drawn" everywhere;
    ///   LinearR32F       `depthTexture` is a linear view-depth R32F texture (FrameBuilder::sceneDepth's contract);
    ///   DepthTexture     `depthTexture` is a GL_TEXTURE_2D depth texture (16, 24, 32F, 24_8) drawn with view.proj;
    ///   BoundFramebuffer the depth attachment of GL_DRAW_FRAMEBUFFER at the call (copied only if a pass reads it).
    enum class DepthSource : uint8_t { None, LinearR32F, DepthTexture, BoundFramebuffer };
    DepthSource depthSource = DepthSource::None;
    uint32_t depthTexture = 0;  ///< GL name for LinearR32F / DepthTexture
    uint32_t depthFormat = 0;   ///< internal format for DepthTexture; 0 = query it
    DepthMapping mapping;       ///< how the host's window depth maps (clip control, depth range)
};

class ImmediateRenderer {
public:
    /// `host` loads the plugin's GL table (may be null once it is loaded); the linearise program
    /// is built into `programs` (Renderers' cache, which outlives this) and read from it.
    ImmediateRenderer(HostAdapter* host, ProgramCache& programs);
    ~ImmediateRenderer();  ///< releaseGl(): the context must be current if anything was allocated
    /// Builds the linearise program into the cache now (Plugin::prepareGl), so the first renderView that reads
    /// the host's z-buffer compiles nothing. False, logged and in `out` ("file:line") when it does
    /// not build.
    bool prepare(Diagnostics* out);
    ImmediateRenderer(const ImmediateRenderer&) = delete;
    ImmediateRenderer& operator=(const ImmediateRenderer&) = delete;

    /// Draws the passes `renderers` declare for `runtimes` under `settings` (Renderers::declare
    /// with this renderer's frame graph, then the running passes in order); `*drawn` (when given)
    /// as Renderers::declare sets it, untouched when refused before declaring. Refused, nothing
    /// drawn: InvalidValue (a depth source outside the enum, an invalid mapping), NullArgument
    /// (no texture for LinearR32F / DepthTexture), InvalidView (as declarePasses),
    /// UnsupportedDepth (a texture of a format it cannot read, a bound framebuffer without a
    /// depth attachment), SizeMismatch (a host texture neither of the view's size nor covering
    /// the view at the viewport's origin),
    /// NoGlContext. Refusals are logged like the plugin's API errors. A linearise program that
    /// does not build is logged (ShaderBuild, also in lastError()); that frame draws as with no depth.
    ErrorCode render(Renderers& renderers, const std::vector<ReactionRuntime>& runtimes,
                     const FrameSettings& settings, const ImmediateView& view, int* drawn = nullptr);
    /// Refusals go to `errors` under "renderView" (counted in Stats::apiErrors, repeats limited)
    /// instead of straight to the host's log. Null: the log.
    void setApiErrors(ApiErrors* errors) { errors_ = errors; }
    /// Frees the pooled targets and the depth copy (context current). The next render allocates again.
    void releaseGl();

    /// Pooled GL targets held now (the produced linear depth among them).
    int targetsAllocated() const { return pool_.allocatedNow(); }
    /// GL targets allocated since creation (reuse keeps it still).
    int targetAllocations() const { return pool_.allocationsEver(); }
    /// Depth copies from a bound framebuffer / linearise passes since creation.
    int depthCopies() const { return depth_.copies(); }
    int depthLinearizations() const { return depth_.linearizations(); }
    /// Where the last render copied and linearised the host's depth (the union of what its running
    /// passes read; whole when a pass reads all of it or nothing narrowed it).
    const DepthRegion& lastDepthRegion() const { return lastRegion_; }
    /// The passes the last render ran, in order.
    const std::vector<std::string>& lastPasses() const { return lastPasses_; }
    const std::string& lastError() const { return lastError_; }

private:
    /// Builds the linearise program into the cache unless its key was tried (a failure is
    /// logged and kept once) and binds it.
    bool ensureDepthProgram();
    /// Logs "fx: error[Code] immediate render: what" and returns `code`.
    ErrorCode refuse(ErrorCode code, const std::string& what);

    HostAdapter* host_;
    ProgramCache& programs_;
    ApiErrors* errors_ = nullptr;
    ImmediateTargetPool pool_;
    DepthLinearizer depth_;
    std::vector<std::string> lastPasses_;
    DepthRegion lastRegion_;
    std::string lastError_;
    bool depthReady_ = false;  ///< this frame's linearise program is there (render sets it)
    std::string depthError_;   ///< why the linearise program's last build failed ("": none failed)
};

}  // namespace fx
