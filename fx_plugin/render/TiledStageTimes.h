#pragma once
// The tiled path's GPU time by stage, for a GPU session (CUBEFX_TILED_STAGE_TIMES=1; off by
// default): fxbench times a pass as a whole, and the tiled pass of a large view is eight stages on
// the GPU whose shares decide what to make cheaper next. A view binned in its pass (TiledPath's
// deferred bins) is marked with GL_TIMESTAMP queries between its stages:
//   order      the particles' keys and their radix passes (TileSort::sortParticles)
//   records    each particle's record (the setup dispatch)
//   bins       the GPU's bins (TileSort::binOnGpu; 0 where the host's threads bin)
//   wait       from the first pass's last dispatch to the second pass's first: the GPU idle while
//              the CPU reads the bins back (or bins) and issues the rest, unless other work ran
//   emit       the pairs' first entries added up and the pairs written
//   pair sort  the pairs' radix passes by tile
//   shade      the tiles
//   composite  the covered tiles onto sceneColor
// Read without a stall a few views later, and logged (LogLevel::Info) as the medians of every
// reportEvery() views: "fx: tiled stages, GPU ms (median of N views, M particles): order ...".
// Timestamps mean nothing on a software rasterizer. Without glQueryCounter and
// glGetQueryObjectui64v (a host that did not give them) nothing is marked.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fx {

class TiledStageTimes {
public:
    enum Mark : int { Start, Ordered, Recorded, Binned, TilesStart, Emitted, Sorted, Shaded, Composited, kMarks };
    static constexpr int kStages = kMarks - 1;
    static constexpr const char* kStageNames[kStages] = {"order", "records", "bins",  "wait",
                                                          "emit",  "pair sort", "shade", "composite"};

    /// CUBEFX_TILED_STAGE_TIMES=1 (read once), or set(); reset() goes back to the environment's.
    static bool on();
    static void set(bool on);
    static void reset();
    /// Views per report (default 64); for tests.
    static void setReportEvery(int views);

    TiledStageTimes() = default;
    ~TiledStageTimes();  // deletes the queries where the plugin's context is current
    TiledStageTimes(const TiledStageTimes&) = delete;
    TiledStageTimes& operator=(const TiledStageTimes&) = delete;

    /// A view's first mark (Start): a new set of queries, once the oldest has been read (a wait
    /// only where the GPU is four views behind). `particles`: the view's, for the report.
    void begin(uint32_t particles);
    /// The timestamp after a stage, in the current set; nothing where no set is open.
    void mark(Mark m);
    /// The last mark (Composited): the set is complete and waits to be read; a set left without
    /// it (a view that fell back) is dropped at the next begin().
    void end();
    /// The report line once reportEvery() views have been read since the last, else "".
    std::string takeReport();
    /// The views read so far (tests).
    uint64_t viewsRead() const { return viewsRead_; }

private:
    static constexpr int kSets = 4;
    struct Set {
        std::array<uint32_t, kMarks> queries{};
        uint32_t marked = 0;  // a bit per mark issued
        uint32_t particles = 0;
        bool pending = false;  // complete, not yet read
    };
    bool available() const;
    void readReady(bool wait);  // reads the complete sets whose results are in (all of the oldest with `wait`)
    std::array<Set, kSets> sets_{};
    int current_ = -1, next_ = 0;
    std::array<std::vector<double>, kStages> samples_{};
    uint32_t lastParticles_ = 0;
    uint64_t viewsRead_ = 0;
    std::string report_;
};

}  // namespace fx
