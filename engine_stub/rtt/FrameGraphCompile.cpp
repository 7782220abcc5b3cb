// FrameGraph::compile(): implicit shared-depth accesses, culling, offers (writeIfRead), the
// z-buffer shared if written, validation and target lifetimes. See FrameGraph.h for the rules.
#include "rtt/FrameGraph.h"

#include <algorithm>

#include "rtt/RenderTargetPool.h"

namespace cube::rtt {

void FrameGraph::expandAccesses() {
    // Done at compile time so a target's shared depth may be set after passes declared it.
    accesses_.clear();
    for (uint32_t pi = 0; pi < passCount_; ++pi) {
        Pass& p = passes_[pi];
        p.accessBegin = uint32_t(accesses_.size());
        for (uint32_t i = p.declaredBegin; i < p.declaredEnd; ++i) {
            const AccessRecord a = declared_[i];
            accesses_.push_back(a);
            // The shared depth is the owner's storage: depth testing reads it, depth writes change it.
            const int owner = resources_[a.resource].sharedDepthOf;
            if (owner >= 0 && (a.access & (kWrite | kReadDepth)))
                accesses_.push_back({uint32_t(owner), uint8_t((a.access & kWrite ? kRead | kWrite : 0) |
                                                              (a.access & kReadDepth) | kImplicit)});
        }
        p.accessEnd = uint32_t(accesses_.size());
    }
}

void FrameGraph::cull() {
    // Walk back from side effects; a pass lives if a live later pass reads what it writes.
    // An offer (kWriteIfRead) notes whether a later kept pass reads its target; it keeps only a
    // pass that does nothing but offer.
    needed_.assign(resourceCount_, 0);
    for (size_t pos = passCount_; pos-- > 0;) {
        Pass& p = passes_[order_[pos]];
        bool kept = p.sideEffect, writes = false, offerRead = false;
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) {
            AccessRecord& a = accesses_[i];
            writes |= (a.access & kWrite) != 0;
            kept |= (a.access & kWrite) && (needed_[a.resource] || resources_[a.resource].persistent);
            if ((a.access & kWriteIfRead) && needed_[a.resource]) {
                a.access |= kReadLater;
                offerRead = true;
            }
        }
        p.offersOnly = !writes && !p.sideEffect && p.accessBegin != p.accessEnd;
        p.kept = kept || (p.offersOnly && offerRead);
        if (!p.kept) continue;
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i)
            if (accesses_[i].access & (kRead | kReadDepth)) needed_[accesses_[i].resource] = 1;
    }
    // Forward: an offer is taken when it is read later, unless an earlier kept pass wrote the
    // target outright or this pass draws into it already through a shared z-buffer (reuses
    // needed_ as "written outright so far"; a taken offer of an offers-only pass is outright).
    std::fill(needed_.begin(), needed_.end(), uint8_t(0));
    for (size_t pos = 0; pos < passCount_; ++pos) {
        const Pass& p = passes_[order_[pos]];
        if (!p.kept) continue;
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) {
            AccessRecord& a = accesses_[i];
            if (!(a.access & kWriteIfRead) || !(a.access & kReadLater) || needed_[a.resource]) continue;
            bool implicit = false;
            for (uint32_t j = p.accessBegin; j < p.accessEnd; ++j)
                implicit |= accesses_[j].resource == a.resource && (accesses_[j].access & kImplicit);
            if (implicit) continue;
            a.access |= kWrite;
            if (p.offersOnly) needed_[a.resource] = 1;
        }
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i)
            if ((accesses_[i].access & (kWrite | kWriteIfRead)) == kWrite) needed_[accesses_[i].resource] = 1;
    }
}

bool FrameGraph::decideSharedDepths() {
    // sharedDepthIfWritten: share when a kept pass writes the owner before the target's first use.
    bool any = false;
    for (uint32_t i = 0; i < resourceCount_; ++i) any |= resources_[i].sharedDepthIfWritten >= 0;
    if (!any) return false;
    firstWrite_.assign(resourceCount_, -1);
    firstUse_.assign(resourceCount_, -1);
    for (size_t pos = 0; pos < passCount_; ++pos) {
        const Pass& p = passes_[order_[pos]];
        if (!p.kept) continue;
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) {
            const AccessRecord& a = accesses_[i];
            if (!(a.access & (kRead | kWrite | kReadDepth))) continue;
            if (firstUse_[a.resource] < 0) firstUse_[a.resource] = int(pos);
            if ((a.access & kWrite) && firstWrite_[a.resource] < 0) firstWrite_[a.resource] = int(pos);
        }
    }
    bool changed = false;
    for (uint32_t i = 0; i < resourceCount_; ++i) {
        Resource& r = resources_[i];
        const int o = r.sharedDepthIfWritten;
        if (o < 0 || firstUse_[i] < 0 || firstWrite_[size_t(o)] < 0 || firstWrite_[size_t(o)] >= firstUse_[i]) continue;
        r.sharedDepthOf = o;
        r.desc.depth = DepthFormat::None;
        changed = true;
    }
    // An owner's depth exists to be shared: dropped when no target took it.
    for (uint32_t i = 0; i < resourceCount_; ++i) {
        const int o = resources_[i].sharedDepthIfWritten;
        if (o < 0) continue;
        bool shared = false;
        for (uint32_t j = 0; j < resourceCount_; ++j) shared |= resources_[j].sharedDepthOf == o;
        if (!shared) resources_[size_t(o)].desc.depth = DepthFormat::None;
    }
    return changed;
}

bool FrameGraph::compile() {
    compiled_ = false;
    report_.error.assign(declError_);
    if (!report_.error.empty()) return false;  // a declaration already failed
    for (uint32_t i = 0; i < resourceCount_; ++i) {  // undo a previous compile's depth decisions
        Resource& r = resources_[i];
        if (r.sharedDepthIfWritten < 0) continue;
        r.sharedDepthOf = -1;
        r.desc.depth = r.ownDepth;
        resources_[size_t(r.sharedDepthIfWritten)].desc.depth = resources_[size_t(r.sharedDepthIfWritten)].ownDepth;
    }

    order_.resize(passCount_);
    for (uint32_t i = 0; i < passCount_; ++i) order_[i] = i;
    std::sort(order_.begin(), order_.end(), [this](uint32_t a, uint32_t b) {
        return passes_[a].order != passes_[b].order ? passes_[a].order < passes_[b].order : a < b;
    });
    expandAccesses();
    cull();
    if (decideSharedDepths()) {  // the shared z-buffer adds accesses to its owner: cull again
        expandAccesses();
        cull();
    }

    for (uint32_t i = 0; i < resourceCount_; ++i) {
        const Resource& r = resources_[i];
        if (r.imported) {
            if (!pool_.isValid(r.handle)) return fail("imported target '" + r.name + "': stale or invalid handle");
            continue;
        }
        if (r.desc.sharedDepth.valid())
            return fail("target '" + r.name + "': use TargetDesc::sharedDepthOf, not a pool handle");
        RenderTargetDesc check = r.desc;
        if (r.sharedDepthOf >= 0) {
            check.sharedDepth = {0, 1};  // stands in for the owner's handle, acquired later
            const Resource& o = resources_[size_t(r.sharedDepthOf)];
            if (o.desc.depth == DepthFormat::None || o.desc.sharedDepth.valid() || o.sharedDepthOf >= 0)
                return fail("target '" + r.name + "': shares the depth of '" + o.name +
                            "', which does not own a depth attachment");
            if (!sameSizeRule(r.desc, o.desc))
                return fail("target '" + r.name + "': SharedDepthSizeMismatch: '" + o.name +
                            "' has a different width/height/scale rule");
        }
        std::string message;
        if (RttError e = validateDesc(check, pool_.limits(), &message); e != RttError::None)
            return fail("target '" + r.name + "': " + rttErrorName(e) + ": " + message);
    }

    // Lifetimes over kept passes; reuse needed_ as "written so far".
    std::fill(needed_.begin(), needed_.end(), uint8_t(0));
    for (uint32_t i = 0; i < resourceCount_; ++i) {
        resources_[i].first = resources_[i].last = -1;
        resources_[i].sampledDepth = false;
    }
    for (size_t pos = 0; pos < passCount_; ++pos) {
        const Pass& p = passes_[order_[pos]];
        if (!p.kept) continue;
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) {
            const AccessRecord& a = accesses_[i];
            if (!(a.access & (kRead | kWrite | kReadDepth))) continue;  // an offer not taken
            Resource& r = resources_[a.resource];
            if (r.first < 0) r.first = int(pos);
            r.last = int(pos);
            if (a.access & kReadDepth) r.sampledDepth = true;
        }
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i) {
            const AccessRecord& a = accesses_[i];
            const Resource& r = resources_[a.resource];
            bool writesHere = false;
            for (uint32_t j = p.accessBegin; j < p.accessEnd; ++j)
                writesHere |= accesses_[j].resource == a.resource && (accesses_[j].access & kWrite);
            if ((a.access & (kRead | kReadDepth)) && !r.imported && !needed_[a.resource] && !writesHere)
                return fail("pass '" + p.name + "' reads '" + r.name + "', which no earlier kept pass writes");
        }
        for (uint32_t i = p.accessBegin; i < p.accessEnd; ++i)
            if (accesses_[i].access & kWrite) needed_[accesses_[i].resource] = 1;
    }
    for (uint32_t i = 0; i < resourceCount_; ++i) {
        Resource& r = resources_[i];
        if (r.sharedDepthOf < 0 || r.first < 0) continue;
        Resource& o = resources_[size_t(r.sharedDepthOf)];  // the owner must be live when r is made
        if (o.first < 0 || o.first > r.first) o.first = r.first;
        if (o.last < 0) o.last = r.first;
    }
    for (uint32_t i = 0; i < resourceCount_; ++i) {
        const Resource& r = resources_[i];
        if (r.imported && r.sampledDepth && pool_.depthTexture(r.handle) == 0)
            return fail("imported target '" + r.name + "' is read as depth but its depth is not a texture");
    }

    size_t culled = 0, notTaken = 0;
    for (size_t pos = 0; pos < passCount_; ++pos) {
        const Pass& p = passes_[order_[pos]];
        if (p.kept) continue;
        if (p.offersOnly)
            setAt(report_.notTaken, notTaken++, p.name);
        else
            setAt(report_.culled, culled++, p.name);
    }
    report_.culled.resize(culled);
    report_.notTaken.resize(notTaken);
    culledAtCompile_ = culled;
    compiled_ = true;
    return true;
}

}  // namespace cube::rtt
