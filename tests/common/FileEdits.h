#pragma once
// Editing a file as a user's editor would, for the tests of live reloads (reaction files, shader
// files): the new text with a modification time of its own, so a poll that compares stamps sees
// every edit even when two land within one tick of the file system's clock.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

namespace cubetest {

/// Writes `text` to `path` (replacing it) and stamps it `secondsAhead` from now.
inline void writeAhead(const std::string& path, const std::string& text, int secondsAhead) {
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << text;
    }
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now() +
                                               std::chrono::seconds(secondsAhead));
}

}  // namespace cubetest
