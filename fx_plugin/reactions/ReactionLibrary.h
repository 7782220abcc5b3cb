#pragma once
// The running reaction set plus hot reload: remembers what was loaded (a file or a directory)
// and, when polled, reloads when a file changed, appeared or disappeared. A reload with any
// error keeps the running set and reports the diagnostics once per change.
//
// Change detection: every poll stats the files (modification time + size). Because two writes
// inside one mtime tick leave the stamp unchanged, a file whose stamp was first seen less than
// kSameTickWindow ago is also re-read and compared by content hash. So a change is seen on the
// first poll after it, at most one poll interval late (default 0.1 s).
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fx/Diagnostic.h"
#include "reactions/ReactionDesc.h"

namespace fx {

class ReactionLibrary {
public:
    enum class PollResult {
        Unchanged,  ///< nothing changed on disk (or too soon since the last poll)
        Reloaded,   ///< a new set went live (current() changed)
        Rejected,   ///< files changed but did not validate; the running set is kept
    };

    /// Loads a file or a directory (loadReactionPath) and watches it from now on. On error
    /// returns false and keeps the running set and the watched path as they were.
    bool load(const std::string& path, Diagnostics* diags);
    /// Reloads when the watched files changed; see PollResult. Cheap when nothing changed
    /// (a stat per file), and does nothing until load() succeeded once.
    PollResult poll(Diagnostics* diags);
    /// An editor's text for one watched file (`file` must be one of current().files, else
    /// FileNotFound): validated with the other files as one set, exactly like a load. On success
    /// the set goes live and `text` stands in for the file's disk content (in this and every
    /// later poll) until load() or the next loadOverride() of that file; on error nothing
    /// changes. Poll still watches the disk stamps, so a later disk change of another file
    /// reloads with this text kept.
    bool loadOverride(const std::string& file, const std::string& text, Diagnostics* diags);

    const ReactionSet& current() const { return current_; }
    bool loaded() const { return loaded_; }
    const std::string& path() const { return path_; }
    /// Counts every set that went live (load or reload), starting at 0 before the first.
    int generation() const { return generation_; }

    /// Minimum time between two polls that look at the disk. Default 0.1 s; 0 checks every call.
    void setPollInterval(double seconds) { pollInterval_ = seconds; }

    /// mtime ticks are 2 s on the coarsest file systems a game ships on (FAT); ext4 is 1 ns.
    static constexpr double kSameTickWindow = 2.5;

private:
    using Clock = std::chrono::steady_clock;

    struct FileState {
        std::string path;
        int64_t mtime = 0;
        uint64_t size = 0;
        uint64_t hash = 0;
        bool readable = false;
        Clock::time_point stampSeen{};  ///< when this (mtime, size) was first observed
    };
    struct Snapshot {
        bool isDirectory = false;
        std::vector<FileState> files;
    };

    /// Stats the watched path: file list and stamps, no contents.
    Snapshot statFiles() const;
    /// Reads every file of `snap` (filling hashes) and validates them as one set.
    bool readAndLoad(Snapshot* snap, ReactionSet* set, Diagnostics* diags) const;

    ReactionSet current_;
    std::map<std::string, std::string> overrides_;  ///< file -> editor text (loadOverride)
    bool loaded_ = false;
    std::string path_;
    Snapshot seen_;
    int generation_ = 0;
    double pollInterval_ = 0.1;
    Clock::time_point lastPoll_{};
};

/// 64-bit FNV-1a of a byte string (content hash for change detection).
uint64_t contentHash(const std::string& bytes);

}  // namespace fx
