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
    const int w = ctx.width(first), h = ctx.height(first);
    const bool secondOk = !second.valid() || (ctx.width(second) == w && ctx.height(second) == h);
    if (w == view.width && h == view.height && secondOk) return true;
    if (report) {
        std::string what = "the scene targets are " + std::to_string(w) + "x" + std::to_string(h);
        if (second.valid()) {
            what += " and " + std::to_string(ctx.width(second)) + "x" + std::to_string(ctx.height(second));
        }
        what += ", ViewInfo " + std::to_string(view.width) + "x" + std::to_string(view.height) +
                "; they must be equal; nothing drawn";
        report(what);
    }
    return false;
}

}  // namespace fx
