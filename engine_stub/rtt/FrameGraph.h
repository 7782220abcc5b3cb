#pragma once
// Declared render passes for one frame (Filament-style, with bgfx-style names and order keys).
//
//   graph.reset();
//   auto depth = graph.create("scene_depth", depthDesc);
//   graph.addPass("depth_prepass", 100, [&](PassBuilder& b) { b.write(depth); },
//                 [&](PassContext& ctx) { ctx.bindForDraw(depth); ... });
//   ...
//   graph.compile();   // culls
//   graph.execute();   // acquires, runs, releases, times
//
// Passes run sorted by (order, declaration index). compile() walks back from side-effect passes
// (and writers of persistent imports): a pass is kept only if a kept pass after it reads a
// target it writes. Culled passes never run; virtual targets only kept passes use are acquired
// from the pool right before their first use and released right after their last use, so
// later passes can reuse them in the same frame. Writes are not versioned: every kept-later
// reader of a target keeps every earlier writer of it (passes may blend onto earlier results).
//
// Where a result comes from can be left to compile() (a depth prepass, or the opaque pass as a
// second render target):
//  - PassBuilder::writeIfRead(t): an offer to write t. It is taken (t allocated and written)
//    only when a later kept pass reads t, no earlier kept pass wrote t outright, and the pass
//    does not already draw into t through a shared z-buffer; the pass asks
//    PassContext::isNeeded(t) as it runs. An offer keeps no pass, except in a pass that only
//    offers (a depth prepass): that pass runs when an offer of it is taken, and is then t's
//    writer outright; untaken, it is listed in report().notTaken, not as culled.
//  - TargetDesc::sharedDepthIfWritten = owner: the target draws on owner's z-buffer when a kept
//    pass writes owner before the target's first use (a prepass laid it down), else on a depth
//    of its own (desc.depth), and owner's depth is dropped. PassContext::sharesDepth(t) says which.
//
// Rebuild it every frame: reset() keeps the graph's storage, and the pool hands back the same
// GL objects, so a steady frame creates no GL objects and allocates little on the heap
// (std::function may for large captures).
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "rtt/FrameGraphReport.h"
#include "rtt/FrameGraphResource.h"
#include "rtt/PassBuilder.h"
#include "rtt/PassContext.h"
#include "rtt/PassTimer.h"
#include "rtt/RenderTargetDesc.h"

namespace cube::rtt {

class RenderTargetPool;

class FrameGraph {
public:
    using ExecuteFn = std::function<void(PassContext&)>;

    /// A virtual target: a RenderTargetDesc (whose sharedDepth pool handle must stay unset) plus
    /// the virtual target whose depth it uses. Defaults: as RenderTargetDesc, no shared depth.
    struct TargetDesc : RenderTargetDesc {
        FrameGraphResource sharedDepthOf;  ///< that target must own its depth (depth != None)
        /// Decided by compile(): that target's z-buffer if a kept pass writes that target before
        /// this one's first use (this desc's depth is then unused), else this desc's own depth
        /// (that target's depth is then dropped: it exists to be shared). Unset: no such choice.
        FrameGraphResource sharedDepthIfWritten;
    };

    /// `softwareRenderer`: Platform::softwareRenderer(), picks the timing method under Auto.
    FrameGraph(RenderTargetPool& pool, bool softwareRenderer, TimingMode timing = TimingMode::Auto);
    ~FrameGraph();
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;

    /// Forgets the declared passes and targets (keeps storage and timing history).
    void reset();

    /// A virtual target, allocated only if a kept pass uses it.
    FrameGraphResource create(const char* name, const RenderTargetDesc& desc);
    FrameGraphResource create(const char* name, const TargetDesc& desc);
    /// Makes a virtual target use `owner`'s depth (or, with an invalid owner, stop sharing and
    /// keep desc.depth None) any time before compile(): a host can declare its scene colour
    /// first and decide once the plugin has declared its passes whether it shares the prepass
    /// z-buffer. Clears the target's own depth format.
    void setSharedDepth(FrameGraphResource target, FrameGraphResource owner);
    /// Changes a virtual target's own depth format any time before compile() (a z-buffer that
    /// turns out to be needed, or not, once later passes are known).
    void setDepthFormat(FrameGraphResource target, DepthFormat depth);
    /// An existing pool target (the host's scene colour, a mirror texture kept across frames).
    /// `persistent`: its contents outlive the frame, so passes writing it are never culled.
    FrameGraphResource import(const char* name, RenderTargetHandle handle, bool persistent = false);

    /// Declares a pass; `setup(PassBuilder&)` runs now and declares reads and writes.
    template <class Setup>
    void addPass(const char* name, int order, Setup&& setup, ExecuteFn execute) {
        PassBuilder builder = beginPass(name, order, std::move(execute));
        setup(builder);
    }
    /// Same, from lists (what a host adapter forwarding fx::FrameBuilder::addPass needs).
    void addPass(const char* name, int order, std::initializer_list<FrameGraphResource> reads,
                 std::initializer_list<FrameGraphResource> writes, ExecuteFn execute,
                 bool sideEffect = false);
    /// Same, from arrays.
    void addPass(const char* name, int order, const FrameGraphResource* reads, size_t readCount,
                 const FrameGraphResource* writes, size_t writeCount, ExecuteFn execute,
                 bool sideEffect = false);

    /// Sorts, culls, resolves fallback writers (writeIfRead) and conditional depth sharing
    /// (sharedDepthIfWritten). False (report().error says why) on a broken graph: a bad descriptor,
    /// a shared depth whose owner has no depth, a kept pass reading a virtual target that no
    /// earlier kept pass writes, readDepth on an imported renderbuffer depth.
    bool compile();
    /// Runs the kept passes (compile() first). Framebuffer bindings and viewport are restored
    /// after each pass. Returns false when not compiled or a target could not be allocated (the
    /// passes using it are skipped and reported as culled; report().error says why).
    bool execute();

    /// Counts, per executed pass, the samples it writes that pass the depth test (a
    /// GL_SAMPLES_PASSED query around the pass, read back at the end of execute(), which then
    /// waits for the GPU). Off by default; benchmarks switch it on for untimed frames. Reported
    /// as PassTiming::fragments, and, where the context has ARB_pipeline_statistics_query, the
    /// fragment shader invocations (with a pass's compute shader invocations where the context
    /// has compute shaders) as PassTiming::shaded.
    void setCountFragments(bool on) { countFragments_ = on; }

    /// Waits for the last execute()'s GPU pass timings (and any older ones still pending) and
    /// puts them in report().timings now (PassTimer::resolvePending). Call after execute().
    void resolveTimings();

    const FrameGraphReport& report() const { return report_; }
    const char* timingMethod() const { return timer_.method(); }
    const PassTimer& timer() const { return timer_; }
    RenderTargetPool& pool() const { return pool_; }
    /// True when the pass named `name` was kept by the last compile(); false when it was culled
    /// or never declared: a check by name asserts declared() first, so that a renamed pass fails
    /// the check instead of passing it vacuously.
    bool isKept(const char* name) const;
    /// True when a pass named `name` was declared since the last reset (kept or culled).
    bool declared(const char* name) const;

private:
    friend class PassBuilder;
    friend class PassContext;
    // kWriteIfRead: declared by writeIfRead; compile() adds kWrite when the write counts.
    // kReadLater: set while culling on a kWriteIfRead whose target a later kept pass reads.
    // kImplicit: an access to a shared depth's owner that expandAccesses() added.
    enum Access : uint8_t {
        kRead = 1, kWrite = 2, kReadDepth = 4, kWriteIfRead = 8, kReadLater = 16, kImplicit = 32
    };
    struct Pass {
        std::string name;
        int order = 0;
        uint32_t declaredBegin = 0, declaredEnd = 0;  // in declared_
        uint32_t accessBegin = 0, accessEnd = 0;      // in accesses_ (compile: with implicit ones)
        bool sideEffect = false;
        bool offersOnly = false;  // every write is writeIfRead (compile)
        bool kept = false;
        bool skipped = false;
        ExecuteFn execute;
    };
    struct Resource {
        std::string name;
        RenderTargetDesc desc;
        int sharedDepthOf = -1;
        int sharedDepthIfWritten = -1;  // decided in compile(); sharedDepthOf is then the answer
        DepthFormat ownDepth = DepthFormat::None;  // desc.depth as declared (compile may drop it)
        bool imported = false;
        bool persistent = false;
        bool sampledDepth = false;
        bool failed = false;
        RenderTargetHandle handle;
        int first = -1, last = -1;  // positions in order_ of the first and last kept use
    };
    struct AccessRecord {
        uint32_t resource;
        uint8_t access;
    };

    /// Reuses the strings already in `v` so a steady frame does not reallocate them.
    static void setAt(std::vector<std::string>& v, size_t i, const std::string& s);
    PassBuilder beginPass(const char* name, int order, ExecuteFn execute);
    void addAccess(uint32_t pass, FrameGraphResource target, uint8_t access);
    void expandAccesses();
    void cull();
    bool decideSharedDepths();
    int resourceIndex(FrameGraphResource target) const;
    bool declared(uint32_t pass, int resource) const;
    bool fail(std::string message);
    void acquire(Resource& r);
    void buildReport();

    RenderTargetPool& pool_;
    PassTimer timer_;
    std::vector<Pass> passes_;
    uint32_t passCount_ = 0;
    std::vector<Resource> resources_;
    uint32_t resourceCount_ = 0;
    std::vector<AccessRecord> declared_;
    std::vector<AccessRecord> accesses_;
    std::vector<uint32_t> order_;  // pass indices sorted by (order, declaration)
    std::vector<uint8_t> needed_;
    std::vector<int> firstWrite_, firstUse_;  // compile scratch: positions in order_, -1 none
    bool compiled_ = false;
    size_t culledAtCompile_ = 0;
    int acquired_ = 0;
    std::string declError_;
    FrameGraphReport report_;
    bool countFragments_ = false;
    std::vector<uint32_t> sampleQueries_;  // one per executed pass, grown as needed
    std::vector<uint32_t> shadedQueries_;  // the same, GL_FRAGMENT_SHADER_INVOCATIONS_ARB
    std::vector<uint32_t> computeQueries_;  // and GL_COMPUTE_SHADER_INVOCATIONS_ARB (GL 4.3)
    int computeCounted_ = -1;               // -1 not asked yet; 1 where compute work is counted
    std::vector<long long> fragments_, shaded_;
};

}  // namespace cube::rtt
