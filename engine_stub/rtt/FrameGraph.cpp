#include "rtt/FrameGraph.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstring>

#include "gl/Gl.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace cube::rtt {

void FrameGraph::setAt(std::vector<std::string>& v, size_t i, const std::string& s) {
    if (i < v.size())
        v[i].assign(s);
    else
        v.push_back(s);
}

FrameGraph::FrameGraph(RenderTargetPool& pool, bool softwareRenderer, TimingMode timing)
    : pool_(pool), timer_(softwareRenderer, timing) {
    report_.timingMethod = timer_.method();
}

FrameGraph::~FrameGraph() {
    // A graph destroyed mid-frame (execute() threw) must not keep pool targets in use.
    for (uint32_t i = 0; i < resourceCount_; ++i)
        if (!resources_[i].imported && pool_.isValid(resources_[i].handle)) pool_.release(resources_[i].handle);
    if (!sampleQueries_.empty()) glDeleteQueries(GLsizei(sampleQueries_.size()), sampleQueries_.data());
    if (!shadedQueries_.empty()) glDeleteQueries(GLsizei(shadedQueries_.size()), shadedQueries_.data());
    if (!computeQueries_.empty()) glDeleteQueries(GLsizei(computeQueries_.size()), computeQueries_.data());
}

void FrameGraph::reset() {
    for (uint32_t i = 0; i < passCount_; ++i) passes_[i].execute = nullptr;  // drop captures now
    passCount_ = 0;
    resourceCount_ = 0;
    declared_.clear();
    compiled_ = false;
    declError_.clear();
    report_.error.clear();
}

FrameGraphResource FrameGraph::create(const char* name, const RenderTargetDesc& desc) {
    TargetDesc d;
    static_cast<RenderTargetDesc&>(d) = desc;
    return create(name, d);
}

FrameGraphResource FrameGraph::create(const char* name, const TargetDesc& desc) {
    if (resourceCount_ == resources_.size()) resources_.emplace_back();
    Resource& r = resources_[resourceCount_];
    r.name.assign(name ? name : "");
    r.desc = desc;
    r.desc.name = "";
    r.sharedDepthOf = desc.sharedDepthOf.valid() ? resourceIndex(desc.sharedDepthOf) : -1;
    if (desc.sharedDepthOf.valid() && r.sharedDepthOf < 0 && declError_.empty())
        declError_ = "target '" + r.name + "': sharedDepthOf is not a target of this frame";
    r.sharedDepthIfWritten = desc.sharedDepthIfWritten.valid() ? resourceIndex(desc.sharedDepthIfWritten) : -1;
    if (desc.sharedDepthIfWritten.valid() && (r.sharedDepthIfWritten < 0 || r.sharedDepthOf >= 0) &&
        declError_.empty())
        declError_ = "target '" + r.name + "': sharedDepthIfWritten is not a target of this frame, or " +
                     "the target also has sharedDepthOf";
    r.ownDepth = r.desc.depth;
    r.imported = r.persistent = r.sampledDepth = r.failed = false;
    r.handle = {};
    r.first = r.last = -1;
    return {++resourceCount_};
}

FrameGraphResource FrameGraph::import(const char* name, RenderTargetHandle handle, bool persistent) {
    if (resourceCount_ == resources_.size()) resources_.emplace_back();
    Resource& r = resources_[resourceCount_];
    r.name.assign(name ? name : "");
    const RenderTargetDesc* d = pool_.desc(handle);
    r.desc = d ? *d : RenderTargetDesc{};
    r.desc.name = "";
    r.sharedDepthOf = r.sharedDepthIfWritten = -1;
    r.ownDepth = r.desc.depth;
    r.imported = true;
    r.persistent = persistent;
    r.sampledDepth = r.failed = false;
    r.handle = handle;
    r.first = r.last = -1;
    return {++resourceCount_};
}

int FrameGraph::resourceIndex(FrameGraphResource target) const {
    return target.id >= 1 && target.id <= resourceCount_ ? int(target.id - 1) : -1;
}

PassBuilder FrameGraph::beginPass(const char* name, int order, ExecuteFn execute) {
    if (passCount_ == passes_.size()) passes_.emplace_back();
    Pass& p = passes_[passCount_];
    p.name.assign(name ? name : "");
    p.order = order;
    p.declaredBegin = p.declaredEnd = uint32_t(declared_.size());
    p.sideEffect = p.kept = p.skipped = p.offersOnly = false;
    p.execute = std::move(execute);
    compiled_ = false;
    return PassBuilder(*this, passCount_++);
}

void FrameGraph::addPass(const char* name, int order, std::initializer_list<FrameGraphResource> reads,
                         std::initializer_list<FrameGraphResource> writes, ExecuteFn execute, bool sideEffect) {
    addPass(name, order, reads.begin(), reads.size(), writes.begin(), writes.size(), std::move(execute),
            sideEffect);
}

void FrameGraph::addPass(const char* name, int order, const FrameGraphResource* reads, size_t readCount,
                         const FrameGraphResource* writes, size_t writeCount, ExecuteFn execute,
                         bool sideEffect) {
    PassBuilder b = beginPass(name, order, std::move(execute));
    for (size_t i = 0; i < readCount; ++i) b.read(reads[i]);
    for (size_t i = 0; i < writeCount; ++i) b.write(writes[i]);
    if (sideEffect) b.sideEffect();
}

void FrameGraph::addAccess(uint32_t pass, FrameGraphResource target, uint8_t access) {
    // Accesses of a pass are contiguous: passes are declared one at a time.
    assert(pass + 1 == passCount_ && "PassBuilder used after the next pass was declared");
    const int r = resourceIndex(target);
    if (r < 0) {
        if (declError_.empty())
            declError_ = "pass '" + passes_[pass].name + "' uses a target that is not part of this frame";
        return;
    }
    declared_.push_back({uint32_t(r), access});
    passes_[pass].declaredEnd = uint32_t(declared_.size());
}

void FrameGraph::setSharedDepth(FrameGraphResource target, FrameGraphResource owner) {
    const int r = resourceIndex(target);
    const int o = owner.valid() ? resourceIndex(owner) : -1;
    if (r < 0 || resources_[size_t(r)].imported || (owner.valid() && (o < 0 || o == r))) {
        if (declError_.empty()) declError_ = "setSharedDepth: not a virtual target of this frame";
        return;
    }
    resources_[size_t(r)].sharedDepthOf = o;
    if (o >= 0) resources_[size_t(r)].desc.depth = resources_[size_t(r)].ownDepth = DepthFormat::None;
    compiled_ = false;
}

void FrameGraph::setDepthFormat(FrameGraphResource target, DepthFormat depth) {
    const int r = resourceIndex(target);
    if (r < 0 || resources_[size_t(r)].imported) {
        if (declError_.empty()) declError_ = "setDepthFormat: not a virtual target of this frame";
        return;
    }
    resources_[size_t(r)].desc.depth = resources_[size_t(r)].ownDepth = depth;
    compiled_ = false;
}

bool FrameGraph::declared(uint32_t pass, int resource) const {
    const Pass& p = passes_[pass];
    for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i)
        if (int(accesses_[i].resource) == resource) return true;
    return false;
}

bool FrameGraph::fail(std::string message) {
    if (report_.error.empty()) report_.error = std::move(message);
    compiled_ = false;
    return false;
}

void FrameGraph::acquire(Resource& r) {
    RenderTargetDesc d = r.desc;
    d.name = r.name.c_str();
    if (r.sampledDepth) d.sampledDepth = true;
    if (r.sharedDepthOf >= 0) d.sharedDepth = resources_[size_t(r.sharedDepthOf)].handle;
    RttError e = RttError::None;
    r.handle = pool_.acquire(d, &e);
    r.failed = e != RttError::None;
    if (r.failed && report_.error.empty())
        report_.error = "target '" + r.name + "': " + rttErrorName(e) + ": " + pool_.lastErrorMessage();
    if (!r.failed) ++acquired_;
}

bool FrameGraph::execute() {
    if (!compiled_) {
        if (report_.error.empty()) report_.error = "execute() without a successful compile()";
        return false;
    }
    const auto started = std::chrono::steady_clock::now();
    acquired_ = 0;
    size_t executed = 0, culled = culledAtCompile_;
    ScopedTargetBinding saved;
    timer_.beginFrame();
    const bool countShaded = countFragments_ && GLAD_GL_ARB_pipeline_statistics_query;
    if (countShaded && computeCounted_ < 0) {
        // A pass that dispatches compute work (the plugin's tiled path) counts its invocations
        // too: GL_COMPUTE_SHADER_INVOCATIONS_ARB exists where compute shaders do (GL 4.3).
        GLint major = 0, minor = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        computeCounted_ = major * 10 + minor >= 43 ? 1 : 0;
    }
    const bool countCompute = countShaded && computeCounted_ == 1;
    for (size_t pos = 0; pos < passCount_; ++pos) {
        Pass& p = passes_[order_[pos]];
        if (!p.kept) continue;
        for (int sharers = 0; sharers < 2; ++sharers) {  // depth owners first
            for (uint32_t i = 0; i < resourceCount_; ++i) {
                Resource& r = resources_[i];
                if (!r.imported && r.first == int(pos) && (r.sharedDepthOf >= 0) == (sharers == 1)) acquire(r);
            }
        }
        p.skipped = false;
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) p.skipped |= resources_[accesses_[i].resource].failed;
        if (!p.skipped && p.execute) {
            gl::DebugGroup group(p.name.c_str());
            if (countFragments_) {
                if (sampleQueries_.size() <= executed) {
                    sampleQueries_.push_back(0);
                    glGenQueries(1, &sampleQueries_.back());
                }
                glBeginQuery(GL_SAMPLES_PASSED, sampleQueries_[executed]);
            }
            if (countShaded) {
                if (shadedQueries_.size() <= executed) {
                    shadedQueries_.push_back(0);
                    glGenQueries(1, &shadedQueries_.back());
                }
                glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, shadedQueries_[executed]);
            }
            if (countCompute) {
                if (computeQueries_.size() <= executed) {
                    computeQueries_.push_back(0);
                    glGenQueries(1, &computeQueries_.back());
                }
                glBeginQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB, computeQueries_[executed]);
            }
            timer_.beginPass(p.name.c_str());
            PassContext ctx(*this, order_[pos]);
            p.execute(ctx);
            ctx.endPass();
            timer_.endPass();
            if (countFragments_) glEndQuery(GL_SAMPLES_PASSED);
            if (countShaded) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
            if (countCompute) glEndQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB);
            saved.restore();
            setAt(report_.executed, executed++, p.name);
        } else if (p.skipped) {
            setAt(report_.culled, culled++, p.name);
        }
        for (uint32_t i = 0; i < resourceCount_; ++i) {
            Resource& r = resources_[i];
            if (!r.imported && r.last == int(pos) && r.handle.valid()) {
                pool_.release(r.handle);
                r.handle = {};
            }
        }
    }
    timer_.endFrame();
    report_.executeCpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    fragments_.assign(executed, -1);
    shaded_.assign(executed, -1);
    if (countFragments_) {
        for (size_t i = 0; i < executed; ++i) {
            GLint64 n = 0;
            glGetQueryObjecti64v(sampleQueries_[i], GL_QUERY_RESULT, &n);
            fragments_[i] = static_cast<long long>(n);
            if (!countShaded) continue;
            n = 0;
            glGetQueryObjecti64v(shadedQueries_[i], GL_QUERY_RESULT, &n);
            shaded_[i] = static_cast<long long>(n);
            if (!countCompute) continue;
            n = 0;
            glGetQueryObjecti64v(computeQueries_[i], GL_QUERY_RESULT, &n);
            shaded_[i] += static_cast<long long>(n);
        }
    }
    report_.executed.resize(executed);
    report_.culled.resize(culled);
    buildReport();
    bool ok = true;
    for (uint32_t i = 0; i < resourceCount_; ++i) ok &= !resources_[i].failed;
    return ok;
}

void FrameGraph::resolveTimings() {
    timer_.resolvePending();
    buildReport();
}

void FrameGraph::buildReport() {
    report_.timings.resize(report_.executed.size());
    for (size_t i = 0; i < report_.executed.size(); ++i) {
        PassTiming& t = report_.timings[i];
        t.name.assign(report_.executed[i]);
        t.lastMs = t.medianMs = -1.0;
        t.samples = 0;
        timer_.stats(t.name.c_str(), &t.lastMs, &t.medianMs, &t.samples);
        t.fragments = i < fragments_.size() ? fragments_[i] : -1;
        t.shaded = i < shaded_.size() ? shaded_[i] : -1;
    }
    const RenderTargetPoolStats st = pool_.stats();
    report_.targetsAcquired = acquired_;
    report_.targetsAllocatedThisFrame = st.allocationsThisFrame;
    report_.targetsLive = st.targetsInUse + st.targetsFree;
    report_.timingMethod = timer_.method();
}

bool FrameGraph::isKept(const char* name) const {
    for (uint32_t i = 0; i < passCount_; ++i)
        if (passes_[i].name == name) return compiled_ && passes_[i].kept;
    return false;
}

bool FrameGraph::declared(const char* name) const {
    for (uint32_t i = 0; i < passCount_; ++i)
        if (passes_[i].name == name) return true;
    return false;
}

// --- PassBuilder -------------------------------------------------------------------------------

FrameGraphResource PassBuilder::declare(FrameGraphResource target, uint8_t access) {
    graph_.addAccess(pass_, target, access);
    return target;
}

FrameGraphResource PassBuilder::read(FrameGraphResource target) { return declare(target, FrameGraph::kRead); }
FrameGraphResource PassBuilder::readDepth(FrameGraphResource target) { return declare(target, FrameGraph::kReadDepth); }
FrameGraphResource PassBuilder::write(FrameGraphResource target) { return declare(target, FrameGraph::kWrite); }
FrameGraphResource PassBuilder::writeIfRead(FrameGraphResource target) {
    return declare(target, FrameGraph::kWriteIfRead);
}

void PassBuilder::sideEffect() { graph_.passes_[pass_].sideEffect = true; }

}  // namespace cube::rtt
