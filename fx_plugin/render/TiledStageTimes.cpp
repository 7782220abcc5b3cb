#include "TiledStageTimes.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "render/PrivateGl.h"

namespace fx {
namespace {

int fromEnvironment() {
    const char* v = std::getenv("CUBEFX_TILED_STAGE_TIMES");
    return v && std::strcmp(v, "1") == 0 ? 1 : 0;
}
const int gFromEnvironment = fromEnvironment();
std::atomic<int> gOn{gFromEnvironment};
std::atomic<int> gReportEvery{64};

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
    return v[mid];
}

}  // namespace

bool TiledStageTimes::on() { return gOn.load(std::memory_order_relaxed) != 0; }
void TiledStageTimes::set(bool on) { gOn.store(on ? 1 : 0, std::memory_order_relaxed); }
void TiledStageTimes::reset() { gOn.store(gFromEnvironment, std::memory_order_relaxed); }
void TiledStageTimes::setReportEvery(int views) { gReportEvery.store(std::max(views, 1), std::memory_order_relaxed); }

TiledStageTimes::~TiledStageTimes() {
    if (!privateGlContextCurrent() || !glDeleteQueries) return;
    for (Set& s : sets_) {
        if (s.queries[0]) glDeleteQueries(kMarks, s.queries.data());
    }
}

bool TiledStageTimes::available() const {
    return glGenQueries && glDeleteQueries && glQueryCounter && glGetQueryObjectiv && glGetQueryObjectui64v;
}

void TiledStageTimes::begin(uint32_t particles) {
    current_ = -1;
    if (!on() || !available()) return;
    readReady(false);
    if (sets_[size_t(next_)].pending) readReady(true);  // the GPU is kSets views behind: wait for them
    Set& s = sets_[size_t(next_)];
    if (!s.queries[0]) glGenQueries(kMarks, s.queries.data());
    s.marked = 0;
    s.pending = false;
    s.particles = particles;
    current_ = next_;
    next_ = (next_ + 1) % kSets;
    mark(Start);
}

void TiledStageTimes::mark(Mark m) {
    if (current_ < 0) return;
    Set& s = sets_[size_t(current_)];
    glQueryCounter(s.queries[size_t(m)], GL_TIMESTAMP);
    s.marked |= 1u << m;
}

void TiledStageTimes::end() {
    if (current_ < 0) return;
    mark(Composited);
    Set& s = sets_[size_t(current_)];
    s.pending = s.marked == (1u << kMarks) - 1u;  // a view that left a stage out is not read
    current_ = -1;
    readReady(false);
}

void TiledStageTimes::readReady(bool wait) {
    // Oldest first: the sets were used in turn from next_ on.
    for (int i = 0; i < kSets; ++i) {
        Set& s = sets_[size_t((next_ + i) % kSets)];
        if (!s.pending) continue;
        if (!wait) {
            GLint ready = 0;
            glGetQueryObjectiv(s.queries[kMarks - 1], GL_QUERY_RESULT_AVAILABLE, &ready);
            if (!ready) return;  // the later ones are not either
        }
        GLuint64 t[kMarks] = {};
        for (int m = 0; m < kMarks; ++m) glGetQueryObjectui64v(s.queries[size_t(m)], GL_QUERY_RESULT, &t[m]);
        for (int stage = 0; stage < kStages; ++stage) {
            const double ns = t[stage + 1] >= t[stage] ? double(t[stage + 1] - t[stage]) : 0.0;
            samples_[size_t(stage)].push_back(ns * 1e-6);
        }
        s.pending = false;
        lastParticles_ = s.particles;
        ++viewsRead_;
        if (samples_[0].size() >= size_t(gReportEvery.load(std::memory_order_relaxed))) {
            char line[512];
            int n = std::snprintf(line, sizeof line, "fx: tiled stages, GPU ms (median of %zu views, %u particles):",
                                  samples_[0].size(), lastParticles_);
            for (int stage = 0; stage < kStages && n > 0 && size_t(n) < sizeof line; ++stage) {
                n += std::snprintf(line + n, sizeof line - size_t(n), "%s %s %.3f", stage == 0 ? "" : ",",
                                   kStageNames[stage], median(samples_[size_t(stage)]));
            }
            report_ = line;
            for (std::vector<double>& v : samples_) v.clear();
        }
    }
}

std::string TiledStageTimes::takeReport() {
    std::string r;
    r.swap(report_);
    return r;
}

}  // namespace fx
