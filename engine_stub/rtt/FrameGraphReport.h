#pragma once
// What the last FrameGraph::execute did, for logs, HUDs and benchmark tables.
#include <string>
#include <vector>

namespace cube::rtt {

struct PassTiming {
    std::string name;
    double lastMs = -1.0;    ///< latest sample (-1 until one arrived: GPU results lag a few frames)
    double medianMs = -1.0;  ///< running median over the timer's history
    int samples = 0;
    /// Samples the pass wrote that passed the depth test (GL_SAMPLES_PASSED) in the last frame;
    /// -1 unless FrameGraph::setCountFragments is on.
    long long fragments = -1;
    /// Fragment shader invocations of the pass in the last frame (GL_FRAGMENT_SHADER_INVOCATIONS_ARB:
    /// also the fragments it discarded, and whatever the driver counts for helper lanes), plus its
    /// compute shader invocations where the context has compute shaders (a compute pass's work
    /// items: the tiled particle path's pixels); -1 unless FrameGraph::setCountFragments is on and
    /// the context has ARB_pipeline_statistics_query.
    long long shaded = -1;
};

/// Defaults: empty, nothing run.
struct FrameGraphReport {
    std::vector<std::string> executed;  ///< passes run, in run order
    std::vector<std::string> culled;    ///< passes culled, in run order
    /// Passes that only offer their writes (PassBuilder::writeIfRead) and were not needed, in
    /// run order: an alternative the graph did not pick, not work it saved.
    std::vector<std::string> notTaken;
    std::vector<PassTiming> timings;    ///< one per executed pass, same order
    int targetsAcquired = 0;            ///< virtual targets the frame took from the pool
    int targetsAllocatedThisFrame = 0;  ///< pool creations since RenderTargetPool::beginFrame
    int targetsLive = 0;                ///< pool targets holding GL objects (in use + free)
    const char* timingMethod = "off";   ///< "cpu-glfinish" | "gpu-timer-query" | "off"
    /// CPU wall ms of the last execute() (issuing every pass: draws, dispatches, uploads; not
    /// the GPU's work, which may still be running when it returns).
    double executeCpuMs = 0.0;
    std::string error;                  ///< compile/allocation problem (empty when none)
};

}  // namespace cube::rtt
