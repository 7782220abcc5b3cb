#pragma once
// Running a program through the shell as a user would, and reading back the files it wrote: what
// the end-to-end tests of cube_game and fxbench (tests/cli, tests/panel, tests/fxbench) share.
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace cubetest {

struct CommandResult {
    int status = -1;       ///< exit code; the caller's `signalledStatus` when a signal ended it; -1 if not started
    std::string output;    ///< its stdout (and stderr where the command line says 2>&1)
    double seconds = 0.0;  ///< wall time of the run
};

/// Runs `cmd` with popen and collects its output until it exits.
inline CommandResult runCommand(const std::string& cmd, int signalledStatus) {
    CommandResult r;
    const auto start = std::chrono::steady_clock::now();
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
    const int st = pclose(p);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : signalledStatus;
    return r;
}

/// The whole file, bytes as they are; empty when it cannot be read.
inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace cubetest
