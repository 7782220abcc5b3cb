#pragma once
// Per-pass timing for the frame graph, by name. On a software renderer GPU timer queries
// measure nothing useful, so it times with a CPU clock (steady_clock) around glFinish; on a real
// GPU it issues GL_TIMESTAMP query pairs and reads them back kRingFrames frames later without
// blocking (a result still not ready when its ring slot comes round again is dropped).
#include <cstdint>
#include <string>
#include <vector>

namespace cube::rtt {

enum class TimingMode : uint8_t {
    Auto,           ///< GpuTimerQuery on hardware, CpuGlFinish on a software renderer
    CpuGlFinish,    ///< glFinish + steady_clock around each pass (serialises CPU and GPU)
    GpuTimerQuery,  ///< GL_TIMESTAMP pairs, results a few frames late
    Off,            ///< no timing, no glFinish
};

class PassTimer {
public:
    static constexpr int kRingFrames = 4;

    /// `softwareRenderer`: Platform::softwareRenderer(). `historyLength`: samples kept per pass
    /// for the median (>= 1).
    PassTimer(bool softwareRenderer, TimingMode mode, int historyLength = 120);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    /// The resolved mode (never Auto).
    TimingMode mode() const { return mode_; }
    /// "cpu-glfinish" | "gpu-timer-query" | "off".
    const char* method() const;

    void beginFrame();
    void beginPass(const char* name);
    void endPass();
    void endFrame();
    /// GPU mode: waits for every frame's queries still pending and records them now, so the
    /// latest sample of a pass is the frame just executed. A host that renders the same pass
    /// names in alternating configurations (fxbench's interleaved modes) calls this after each
    /// frame; otherwise results arriving frames late are filed under whichever configuration
    /// happens to be current. Cheap right after a glFinish (the results are ready). No-op in
    /// the other modes.
    void resolvePending();

    /// Latest and running-median milliseconds of pass `name` over the last historyLength
    /// samples; false (values untouched) when no sample has arrived yet.
    bool stats(const char* name, double* lastMs, double* medianMs, int* samples) const;
    /// The pass's kept samples, oldest first (empty when unknown).
    void history(const char* name, std::vector<float>* out) const;
    /// GPU results dropped because they were still unavailable kRingFrames frames later.
    int droppedFrames() const { return dropped_; }

private:
    struct Track {
        std::string name;
        std::vector<float> ring;
        int next = 0;
        int count = 0;
        float last = 0.0f;
    };
    struct GpuFrame {
        std::vector<uint32_t> queries;  // 2 per pass: begin, end
        std::vector<std::string> names;
        int count = 0;
        bool pending = false;
    };

    void record(const char* name, double ms);
    const Track* find(const char* name) const;
    void collectGpuResults();

    TimingMode mode_;
    int historyLength_;
    std::vector<Track> tracks_;
    mutable std::vector<float> scratch_;
    // CPU mode
    int64_t passStartNs_ = 0;
    const char* passName_ = "";
    // GPU mode
    GpuFrame frames_[kRingFrames];
    int current_ = 0;
    uint64_t frameCounter_ = 0;
    int dropped_ = 0;
};

}  // namespace cube::rtt
