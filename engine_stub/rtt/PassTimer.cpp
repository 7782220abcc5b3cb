#include "rtt/PassTimer.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstring>

#include "gl/Gl.h"

namespace cube::rtt {

namespace {
int64_t nowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
}  // namespace

PassTimer::PassTimer(bool softwareRenderer, TimingMode mode, int historyLength)
    : mode_(mode == TimingMode::Auto
                ? (softwareRenderer ? TimingMode::CpuGlFinish : TimingMode::GpuTimerQuery)
                : mode),
      historyLength_(std::max(historyLength, 1)) {
    scratch_.reserve(size_t(historyLength_));  // stats() must not allocate as the history fills
}

PassTimer::~PassTimer() {
    for (GpuFrame& f : frames_)
        if (!f.queries.empty()) glDeleteQueries(GLsizei(f.queries.size()), f.queries.data());
}

const char* PassTimer::method() const {
    switch (mode_) {
        case TimingMode::CpuGlFinish: return "cpu-glfinish";
        case TimingMode::GpuTimerQuery: return "gpu-timer-query";
        case TimingMode::Off:
        case TimingMode::Auto: break;
    }
    return "off";
}

void PassTimer::beginFrame() {
    if (mode_ != TimingMode::GpuTimerQuery) return;
    collectGpuResults();
    current_ = int(frameCounter_++ % kRingFrames);
    GpuFrame& f = frames_[current_];
    if (f.pending) ++dropped_;  // re-issuing its queries discards the old results
    f.pending = false;
    f.count = 0;
}

void PassTimer::beginPass(const char* name) {
    switch (mode_) {
        case TimingMode::CpuGlFinish:
            glFinish();  // earlier work must not be charged to this pass
            passName_ = name;
            passStartNs_ = nowNs();
            break;
        case TimingMode::GpuTimerQuery: {
            GpuFrame& f = frames_[current_];
            const size_t need = size_t(f.count + 1) * 2u;
            if (f.queries.size() < need) {
                const size_t old = f.queries.size();
                f.queries.resize(need);
                glGenQueries(GLsizei(need - old), f.queries.data() + old);
            }
            if (f.names.size() < size_t(f.count + 1)) f.names.resize(size_t(f.count + 1));
            f.names[size_t(f.count)].assign(name);
            glQueryCounter(f.queries[size_t(f.count) * 2u], GL_TIMESTAMP);
            break;
        }
        case TimingMode::Off:
        case TimingMode::Auto: break;
    }
}

void PassTimer::endPass() {
    switch (mode_) {
        case TimingMode::CpuGlFinish:
            glFinish();
            record(passName_, double(nowNs() - passStartNs_) * 1e-6);
            break;
        case TimingMode::GpuTimerQuery: {
            GpuFrame& f = frames_[current_];
            glQueryCounter(f.queries[size_t(f.count) * 2u + 1u], GL_TIMESTAMP);
            ++f.count;
            break;
        }
        case TimingMode::Off:
        case TimingMode::Auto: break;
    }
}

void PassTimer::endFrame() {
    if (mode_ != TimingMode::GpuTimerQuery) return;
    frames_[current_].pending = frames_[current_].count > 0;
    // Headless contexts never swap; without a flush the queries might never reach the GPU and
    // their results never become available. A flush does not wait.
    if (frames_[current_].pending) glFlush();
}

void PassTimer::collectGpuResults() {
    // Oldest first; a frame is complete when its last query is, and later frames cannot be
    // complete before earlier ones, so stop at the first that is not.
    for (int age = 1; age <= kRingFrames; ++age) {
        GpuFrame& f = frames_[(current_ + age) % kRingFrames];
        if (!f.pending) continue;
        GLint available = 0;
        glGetQueryObjectiv(f.queries[size_t(f.count) * 2u - 1u], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) break;
        for (int i = 0; i < f.count; ++i) {
            GLuint64 begin = 0, end = 0;
            glGetQueryObjectui64v(f.queries[size_t(i) * 2u], GL_QUERY_RESULT, &begin);
            glGetQueryObjectui64v(f.queries[size_t(i) * 2u + 1u], GL_QUERY_RESULT, &end);
            record(f.names[size_t(i)].c_str(), end > begin ? double(end - begin) * 1e-6 : 0.0);
        }
        f.pending = false;
    }
}

void PassTimer::resolvePending() {
    if (mode_ != TimingMode::GpuTimerQuery) return;
    for (int age = 1; age <= kRingFrames; ++age) {  // oldest first, the current frame last
        GpuFrame& f = frames_[(current_ + age) % kRingFrames];
        if (!f.pending) continue;
        for (int i = 0; i < f.count; ++i) {
            GLuint64 begin = 0, end = 0;  // GL_QUERY_RESULT waits for the GPU
            glGetQueryObjectui64v(f.queries[size_t(i) * 2u], GL_QUERY_RESULT, &begin);
            glGetQueryObjectui64v(f.queries[size_t(i) * 2u + 1u], GL_QUERY_RESULT, &end);
            record(f.names[size_t(i)].c_str(), end > begin ? double(end - begin) * 1e-6 : 0.0);
        }
        f.pending = false;
    }
}

void PassTimer::record(const char* name, double ms) {
    Track* t = const_cast<Track*>(find(name));
    if (!t) {
        tracks_.emplace_back();
        t = &tracks_.back();
        t->name = name;
        t->ring.assign(size_t(historyLength_), 0.0f);
    }
    t->last = float(ms);
    t->ring[size_t(t->next)] = float(ms);
    t->next = (t->next + 1) % historyLength_;
    t->count = std::min(t->count + 1, historyLength_);
}

const PassTimer::Track* PassTimer::find(const char* name) const {
    for (const Track& t : tracks_)
        if (std::strcmp(t.name.c_str(), name) == 0) return &t;
    return nullptr;
}

bool PassTimer::stats(const char* name, double* lastMs, double* medianMs, int* samples) const {
    const Track* t = find(name);
    if (!t || t->count == 0) return false;
    scratch_.assign(t->ring.begin(), t->ring.begin() + t->count);
    const size_t mid = scratch_.size() / 2;
    std::nth_element(scratch_.begin(), scratch_.begin() + std::ptrdiff_t(mid), scratch_.end());
    double median = scratch_[mid];
    if (scratch_.size() % 2 == 0) {
        const float lower = *std::max_element(scratch_.begin(), scratch_.begin() + std::ptrdiff_t(mid));
        median = 0.5 * (median + double(lower));
    }
    if (lastMs) *lastMs = t->last;
    if (medianMs) *medianMs = median;
    if (samples) *samples = t->count;
    return true;
}

void PassTimer::history(const char* name, std::vector<float>* out) const {
    out->clear();
    const Track* t = find(name);
    if (!t) return;
    const int start = t->count < historyLength_ ? 0 : t->next;
    for (int i = 0; i < t->count; ++i) out->push_back(t->ring[size_t((start + i) % historyLength_)]);
}

}  // namespace cube::rtt
