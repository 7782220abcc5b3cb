#pragma once
// Full resolution (the default path): the billboard particles drawn straight into sceneColor.
//   "particles"             reads sceneDepth only if a visible batch is soft or spherical (and
//                           the opacity map for lit smoke), writes sceneColor
//   "particles_tile_depth"  with fade classification on (FrameSettings::classify) and a soft or
//                           spherical batch visible, first: reads sceneDepth, writes
//                           "particles_tiles" and "particles_tiles_coarse" (FadeClassifier.h),
//                           which "particles" reads too
// Hard particles test the host's z-buffer (no writes; LEQUAL, GEQUAL under reversed-Z), soft and
// spherical ones compare linear depths in the shader (ParticleRenderer.h).
//
// The fade classifier is built by prepareGl when classification is on (else while the first frame
// with it on is declared), from the files of the running programs; one that does not build is
// logged once and the particles are drawn unclassified.
#include <memory>
#include <string>
#include <vector>

#include "FadeClassifier.h"
#include "ParticleDraw.h"
#include "RendererConfig.h"
#include "ShaderLoader.h"

namespace fx {

class FullResPath {
public:
    static constexpr const char* kPass = "particles";

    FullResPath(ParticleDraw& draw, HostAdapter* host, SizeMismatchReport sizeMismatch);
    FullResPath(const FullResPath&) = delete;
    FullResPath& operator=(const FullResPath&) = delete;

    /// Declares the view's passes. `sources`: the running programs' files (the classifier's).
    void declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& view, const ShaderReader& sources);

    /// The classes counted by the last pass that ran with counting on; a frame declared without
    /// classification and counting forgets them.
    FadeClassCounts counts() const { return counts_; }
    void forgetCountsUnless(const FrameSettings& settings) {
        if (!(settings.classify && settings.countClasses)) counts_ = FadeClassCounts{};
    }

    /// The classifier once built (null before: a shader reload rebuilds only one in use).
    FadeClassifier* classifier() { return classifier_.get(); }
    /// A shader reload went live: a classifier in use is replaced by `rebuilt`, and one that had
    /// failed to build gets another try with the new files. Returns what is left to delete (the
    /// old classifier, or `rebuilt` when none was in use), inside the caller's guard.
    std::unique_ptr<FadeClassifier> adoptReload(std::unique_ptr<FadeClassifier> rebuilt);

    /// Builds the fade classifier (its tile and counting programs, and the classified particle
    /// programs into the draw's cache) from `sources`, the running programs' files, unless built;
    /// false when it does not build (tried once until a shader reload). With `failures` its
    /// "file:line" lines go there for the caller to report (prepareGl); without, they are logged.
    bool ensureClassifier(const ShaderReader& sources, std::vector<std::string>* failures = nullptr);

private:

    ParticleDraw& draw_;
    HostAdapter* host_;
    SizeMismatchReport sizeMismatch_;
    std::unique_ptr<FadeClassifier> classifier_;
    bool classifierFailed_ = false;
    FadeClassCounts counts_;
};

}  // namespace fx
