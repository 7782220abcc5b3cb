#include "RendererConfig.h"

#include "PrivateGlLoader.h"

namespace fx {

void logTo(const RendererConfig& config, LogLevel level, const std::string& message) {
    if (config.host) config.host->log(level, message.c_str());
}

bool loadGlFor(const RendererConfig& config, const char* what, Diagnostics* diagnostics) {
    std::string error;
    if (loadPrivateGlOrDiagnose(config.host, diagnostics, &error)) return true;
    logTo(config, LogLevel::Error, std::string("fx: ") + what + " disabled: " + error);
    return false;
}

bool targetsFitView(PassContext& ctx, const ViewInfo& view, Target first, Target second,
                    const SizeMismatchReport& report) {
    // The view's size, or (API 2.1) the size of the target the view is a rectangle of.
    const int tw = view.targetWidth > 0 ? view.targetWidth : view.width;
    const int th = view.targetHeight > 0 ? view.targetHeight : view.height;
    auto fits = [&](Target t) {
        const int tw_ = ctx.width(t), th_ = ctx.height(t);
        return (tw_ == view.width && th_ == view.height) || (tw_ == tw && th_ == th);
    };
    const int w = ctx.width(first), h = ctx.height(first);
    if (fits(first) && (!second.valid() || fits(second))) return true;
    if (report) {
        std::string what = "the scene targets are " + std::to_string(w) + "x" + std::to_string(h);
        if (second.valid()) {
            what += " and " + std::to_string(ctx.width(second)) + "x" + std::to_string(ctx.height(second));
        }
        what += ", ViewInfo " + std::to_string(view.width) + "x" + std::to_string(view.height);
        if (tw != view.width || th != view.height) what += " in a target of " + std::to_string(tw) + "x" + std::to_string(th);
        what += "; each must be the view's size or its target's; nothing drawn";
        report(what);
    }
    return false;
}

}  // namespace fx
