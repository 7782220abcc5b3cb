#include "ReactionLibrary.h"

#include <filesystem>
#include <system_error>

#include "ReactionLoader.h"

namespace fx {

namespace fs = std::filesystem;

uint64_t contentHash(const std::string& bytes) {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

namespace {

bool sameFiles(const std::vector<std::string>& a, const std::vector<std::string>& b) {
    return a == b;
}

}  // namespace

ReactionLibrary::Snapshot ReactionLibrary::statFiles() const {
    Snapshot snap;
    std::error_code ec;
    snap.isDirectory = fs::is_directory(path_, ec);
    std::vector<std::string> paths;
    if (snap.isDirectory) {
        listReactionFiles(path_, &paths, nullptr);  // unlistable = no files; reported on load
    } else {
        paths.push_back(path_);
    }
    for (const std::string& p : paths) {
        FileState f;
        f.path = p;
        std::error_code fe;
        auto mtime = fs::last_write_time(p, fe);
        if (!fe) {
            f.mtime = static_cast<int64_t>(mtime.time_since_epoch().count());
            f.size = fs::file_size(p, fe);
            f.readable = !fe;
        }
        snap.files.push_back(f);
    }
    return snap;
}

bool ReactionLibrary::readAndLoad(Snapshot* snap, ReactionSet* set, Diagnostics* diags) const {
    if (snap->isDirectory && snap->files.empty()) {
        if (diags) diags->push_back({ErrorCode::FileNotFound, path_, 0, 0, "", "directory holds no *.yaml file"});
        return false;
    }
    std::vector<ReactionSource> sources;
    bool ok = true;
    for (FileState& f : snap->files) {
        ReactionSource src;
        src.name = f.path;
        f.readable = readReactionFileText(f.path, &src.text, diags);
        f.hash = f.readable ? contentHash(src.text) : 0;  // of the disk bytes: change detection
        const auto edited = overrides_.find(f.path);
        if (edited != overrides_.end()) {
            src.text = edited->second;
            sources.push_back(std::move(src));
        } else if (f.readable) {
            sources.push_back(std::move(src));
        } else {
            ok = false;
        }
    }
    ok = loadReactionSources(sources, set, diags) && ok;
    return ok;
}

bool ReactionLibrary::load(const std::string& path, Diagnostics* diags) {
    std::string previous = path_;
    path_ = path;
    Snapshot snap = statFiles();
    ReactionSet set;
    Diagnostics local;
    bool ok = readAndLoad(&snap, &set, &local);
    if (diags) diags->insert(diags->end(), local.begin(), local.end());
    if (!ok) {
        path_ = previous;
        return false;
    }
    const Clock::time_point now = Clock::now();
    for (FileState& f : snap.files) f.stampSeen = now;
    seen_ = std::move(snap);
    current_ = std::move(set);
    overrides_.clear();
    loaded_ = true;
    ++generation_;
    lastPoll_ = now;
    return true;
}

bool ReactionLibrary::loadOverride(const std::string& file, const std::string& text, Diagnostics* diags) {
    bool watched = false;
    for (const std::string& f : current_.files) watched = watched || f == file;
    if (!loaded_ || !watched) {
        if (diags) {
            diags->push_back({ErrorCode::FileNotFound, file, 0, 0, "",
                              "not one of the loaded reaction files; expected one of the running set's files"});
        }
        return false;
    }
    std::vector<ReactionSource> sources;
    bool ok = true;
    for (const std::string& f : current_.files) {
        ReactionSource src;
        src.name = f;
        const auto edited = overrides_.find(f);
        if (f == file) {
            src.text = text;
        } else if (edited != overrides_.end()) {
            src.text = edited->second;
        } else if (!readReactionFileText(f, &src.text, diags)) {
            ok = false;
            continue;
        }
        sources.push_back(std::move(src));
    }
    ReactionSet set;
    Diagnostics local;
    ok = loadReactionSources(sources, &set, &local) && ok;
    if (diags) diags->insert(diags->end(), local.begin(), local.end());
    if (!ok) return false;
    overrides_[file] = text;
    current_ = std::move(set);
    ++generation_;
    return true;
}

ReactionLibrary::PollResult ReactionLibrary::poll(Diagnostics* diags) {
    if (!loaded_) return PollResult::Unchanged;
    const Clock::time_point now = Clock::now();
    const auto interval = std::chrono::duration<double>(pollInterval_);
    if (pollInterval_ > 0.0 && now - lastPoll_ < interval) return PollResult::Unchanged;
    lastPoll_ = now;

    Snapshot snap = statFiles();
    std::vector<std::string> before, after;
    for (const FileState& f : seen_.files) before.push_back(f.path);
    for (const FileState& f : snap.files) after.push_back(f.path);
    bool changed = snap.isDirectory != seen_.isDirectory || !sameFiles(before, after);
    if (!changed) {
        for (size_t i = 0; i < snap.files.size(); ++i) {
            FileState& f = snap.files[i];
            const FileState& old = seen_.files[i];
            if (f.readable != old.readable || f.mtime != old.mtime || f.size != old.size) {
                f.stampSeen = now;
                changed = true;
            } else {
                f.hash = old.hash;
                f.stampSeen = old.stampSeen;
            }
        }
    }
    if (!changed) {
        // Same stamp: only a write within the stamp's own mtime tick can hide, so only stamps
        // seen recently are re-read.
        const auto window = std::chrono::duration<double>(kSameTickWindow);
        for (const FileState& f : snap.files) {
            if (!f.readable || now - f.stampSeen >= window) continue;
            std::string text;
            if (!readReactionFileText(f.path, &text, nullptr) || contentHash(text) != f.hash) {
                changed = true;
                break;
            }
        }
        if (!changed) return PollResult::Unchanged;
    }
    for (FileState& f : snap.files) {
        if (f.stampSeen == Clock::time_point{}) f.stampSeen = now;
    }

    ReactionSet set;
    Diagnostics local;
    bool ok = readAndLoad(&snap, &set, &local);

    // Touched but not changed (same files, same bytes): nothing to do, nothing to report again.
    bool sameContent = sameFiles(before, after) && snap.isDirectory == seen_.isDirectory;
    for (size_t i = 0; sameContent && i < snap.files.size(); ++i) {
        sameContent = snap.files[i].readable == seen_.files[i].readable &&
                      snap.files[i].hash == seen_.files[i].hash;
    }
    seen_ = std::move(snap);
    if (sameContent) return PollResult::Unchanged;

    if (!ok) {
        if (diags) diags->insert(diags->end(), local.begin(), local.end());
        return PollResult::Rejected;
    }
    current_ = std::move(set);
    ++generation_;
    return PollResult::Reloaded;
}

}  // namespace fx
