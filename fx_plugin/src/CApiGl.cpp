// The C boundary's (GL) entries (fx/fx.h, "GL"): every one checks its arguments, then that the GL
// table is loaded and a context is current, before it makes a GL call.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "CApiEntries.h"
#include "../render/ImmediateRenderer.h"
#include "../render/PrivateGlLoader.h"
#include "WorldBasis.h"

namespace fx {
namespace capi {
namespace {

// API 2.0's fxViewDesc ended with depthRangeFar; 2.1 appended the viewport fields. A 2.0 host's
// descriptor is read up to its size, the rest as 0.
constexpr size_t kViewDescSize20 = offsetof(fxViewDesc, viewportX);

/// A (GL) call's first check after its arguments: the table is loaded (through this plugin's host
/// when it is not yet) and a context is current; else NoGlContext, refused before any GL call so
/// nothing is marked tried or failed (a later call with a context goes ahead).
ErrorCode glReady(fxPlugin* p, const char* function, std::string* why = nullptr) {
    std::string error;
    if (privateGlLoaded() || loadPrivateGl(p->host, &error)) {
        if (privateGlContextCurrent()) return ErrorCode::None;
        error = "no GL context is current on the calling thread (glGetString(GL_VERSION) gave null)";
    }
    if (why) *why = error;
    return refuse(p, ErrorCode::NoGlContext, function, error);
}

}  // namespace

fxBool prepareGl(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!usable(p, "prepareGl")) return 0;
    std::string why;
    if (glReady(p, "prepareGl", &why) != ErrorCode::None) {
        // The sink hears it too: a host that reads only diagnostics still learns why.
        report(Diagnostics{Diagnostic{ErrorCode::NoGlContext, "", 0, 0, "", why}}, out);
        return 0;
    }
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).prepareGl(d); });
}
fxBool pollShaderReload(fxPlugin* p, const fxDiagnosticSink* out) {
    if (!usable(p, "pollShaderReload")) return 0;
    if (glReady(p, "pollShaderReload") != ErrorCode::None) return 0;
    return withDiagnostics(out, [&](Diagnostics* d) { return impl(p).pollShaderReload(d); });
}

namespace {

/// Checks a view descriptor and turns it into the plugin's right-handed, Y-up ViewInfo; None or
/// the refusal (logged under `function`). `placed`: the descriptor's viewport fields place the
/// view (declarePasses); renderView takes the host's GL viewport instead and does not read them.
ErrorCode viewFrom(const fxPlugin* p, const fxViewDesc* v, const char* function, ViewInfo* out, bool placed = true) {
    if (!v) return refuse(p, ErrorCode::NullArgument, function, "view is null; expected an fxViewDesc");
    if (!knownSize(v->size, sizeof *v, kViewDescSize20)) {
        return refuse(p, ErrorCode::BadDescriptor, function, sizeProblem("fxViewDesc", v->size, sizeof *v, kViewDescSize20));
    }
    const fxViewDesc full = fullDesc(*v);
    v = &full;
    if (v->handedness != FX_RIGHT_HANDED && v->handedness != FX_LEFT_HANDED) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "handedness " + std::to_string(v->handedness) + "; expected FX_RIGHT_HANDED or FX_LEFT_HANDED");
    }
    if (v->depthOrder != FX_DEPTH_STANDARD && v->depthOrder != FX_DEPTH_REVERSED_Z) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "depthOrder " + std::to_string(v->depthOrder) + "; expected FX_DEPTH_STANDARD or FX_DEPTH_REVERSED_Z");
    }
    if (v->width <= 0 || v->height <= 0 || v->width > FX_MAX_VIEW_SIZE || v->height > FX_MAX_VIEW_SIZE) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "size " + std::to_string(v->width) + "x" + std::to_string(v->height) + "; expected 1 .. " +
                          std::to_string(FX_MAX_VIEW_SIZE) + " (FX_MAX_VIEW_SIZE) each");
    }
    if (placed && (v->viewportX < 0 || v->viewportY < 0 || v->targetWidth < 0 || v->targetHeight < 0 ||
        (v->targetWidth > 0 && int64_t(v->viewportX) + v->width > v->targetWidth) ||
        (v->targetHeight > 0 && int64_t(v->viewportY) + v->height > v->targetHeight) ||
        ((v->viewportX > 0 || v->viewportY > 0) && (v->targetWidth == 0 || v->targetHeight == 0)))) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "viewport (" + std::to_string(v->viewportX) + ", " + std::to_string(v->viewportY) + ", " +
                          std::to_string(v->width) + ", " + std::to_string(v->height) + ") in a target of " +
                          std::to_string(v->targetWidth) + "x" + std::to_string(v->targetHeight) +
                          "; expected it inside the target (a view away from (0, 0) gives the target's size)");
    }
    bool finite = finite3(v->eye) && std::isfinite(v->nearPlane) && std::isfinite(v->farPlane) &&
                  std::isfinite(v->depthRangeNear) && std::isfinite(v->depthRangeFar);
    for (int i = 0; i < 16; ++i) finite = finite && std::isfinite(v->view[i]) && std::isfinite(v->proj[i]);
    if (!finite) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "a NaN or infinite value in view, proj, eye, the planes or the depth range; expected finite values");
    }
    if (!(v->nearPlane > 0.0f) || !(v->farPlane > v->nearPlane)) {
        return refuse(p, ErrorCode::InvalidView, function,
                      "near " + std::to_string(v->nearPlane) + ", far " + std::to_string(v->farPlane) +
                          "; expected 0 < near < far");
    }
    *out = rightHandedView(*v, p->up);
    if (!placed) {
        out->x = out->y = 0;
        out->targetWidth = out->targetHeight = 0;
    }
    return ErrorCode::None;
}

/// The view and the frame builder of a declare call, checked (the refusal logged under `function`).
ErrorCode viewAndFrame(const fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, const char* function,
                       ViewInfo* view) {
    const ErrorCode bad = viewFrom(p, v, function, view);
    if (bad != ErrorCode::None) return bad;
    const std::string frameBad = frameBuilderProblem(f);
    if (frameBad.empty()) return ErrorCode::None;
    return refuse(p, f && knownSize(f->size, sizeof *f, offsetof(fxFrameBuilder, sceneZBuffer)) ? ErrorCode::NullArgument
                                                                                                : ErrorCode::BadDescriptor,
                  function, frameBad);
}

}  // namespace

int declarePasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f) {
    if (!usable(p, "declarePasses")) return handleError(p);
    ViewInfo view;
    const ErrorCode bad = viewAndFrame(p, v, f, "declarePasses", &view);
    if (bad != ErrorCode::None) return code(bad);
    const ErrorCode noGl = glReady(p, "declarePasses");
    if (noGl != ErrorCode::None) return code(noGl);
    CFrameBuilder frame(*f, p->impl->apiErrors());
    return code(impl(p).declarePasses(view, frame));
}

namespace {

/// The shadow passes of both entries into *out (this library's struct, zeroed: no smoke), the
/// refusals logged under `function`.
int shadowPasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, const char* function,
                 fxSmokeShadow2* out) {
    std::memset(out, 0, sizeof *out);
    out->size = sizeof *out;
    ViewInfo view;
    const ErrorCode bad = viewAndFrame(p, v, f, function, &view);
    if (bad != ErrorCode::None) return code(bad);
    const ErrorCode noGl = glReady(p, function);
    if (noGl != ErrorCode::None) return code(noGl);
    CFrameBuilder frame(*f, p->impl->apiErrors());
    const SmokeShadow s = impl(p).declareShadowPasses(view, frame);
    if (s.valid()) {
        out->opacity = s.opacity.id;
        const glm::mat4 hostWorldToShadow = fromHostWorld(p->up, s.worldToShadow);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) out->worldToShadow[c * 4 + r] = hostWorldToShadow[c][r];
    }
    return FX_ERROR_NONE;
}

}  // namespace

int declareShadowPasses(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, fxSmokeShadow* out) {
    if (!usable(p, "declareShadowPasses")) return handleError(p);
    if (!out) {
        return code(refuse(p, ErrorCode::NullArgument, "declareShadowPasses",
                           "out is null; expected an fxSmokeShadow for the opacity map"));
    }
    // 2.0 wrote its struct whole, refused or not: no smoke unless the passes were declared.
    fxSmokeShadow2 s;
    const int error = shadowPasses(p, v, f, "declareShadowPasses", &s);
    out->opacity = s.opacity;
    std::memcpy(out->worldToShadow, s.worldToShadow, sizeof out->worldToShadow);
    return error;
}

int declareShadowPasses2(fxPlugin* p, const fxViewDesc* v, const fxFrameBuilder* f, fxSmokeShadow2* out) {
    if (!usable(p, "declareShadowPasses2")) return handleError(p);
    int error = FX_ERROR_NONE;
    if (!outUsable(p, out, "fxSmokeShadow2", "declareShadowPasses2", &error)) return error;
    fxSmokeShadow2 s;
    error = shadowPasses(p, v, f, "declareShadowPasses2", &s);
    if (error == FX_ERROR_NONE) writeOut(out, s, out->size);
    return error;
}

int renderView(fxPlugin* p, const fxViewDesc* v) {
    if (!usable(p, "renderView")) return handleError(p);
    ViewInfo view;
    const ErrorCode bad = viewFrom(p, v, "renderView", &view, false);
    if (bad != ErrorCode::None) return code(bad);
    ImmediateView iv;
    iv.view = view;
    switch (v->depthSource) {
    case FX_DEPTH_FROM_FRAMEBUFFER: iv.depthSource = ImmediateView::DepthSource::BoundFramebuffer; break;
    case FX_DEPTH_FROM_TEXTURE: iv.depthSource = ImmediateView::DepthSource::DepthTexture; break;
    case FX_DEPTH_FROM_LINEAR: iv.depthSource = ImmediateView::DepthSource::LinearR32F; break;
    case FX_DEPTH_FROM_NOTHING: iv.depthSource = ImmediateView::DepthSource::None; break;
    default:
        return code(refuse(p, ErrorCode::InvalidValue, "renderView",
                           "depthSource " + std::to_string(v->depthSource) + "; expected an FX_DEPTH_FROM_* value"));
    }
    iv.depthTexture = v->depthTexture;
    iv.mapping.clipZeroToOne = v->clipDepthZeroToOne != 0;
    const bool defaultRange = v->depthRangeNear == 0.0f && v->depthRangeFar == 0.0f;
    iv.mapping.rangeNear = defaultRange ? 0.0f : v->depthRangeNear;
    iv.mapping.rangeFar = defaultRange ? 1.0f : v->depthRangeFar;
    const ErrorCode noGl = glReady(p, "renderView");
    if (noGl != ErrorCode::None) return code(noGl);
    return code(impl(p).renderImmediate(iv));
}

}  // namespace capi
}  // namespace fx
