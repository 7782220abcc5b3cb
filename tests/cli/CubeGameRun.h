#pragma once
// What the hostile-input tests of tests/cli share: running cube_game under a time bound and a
// scratch folder per test that is removed afterwards.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "RunCommand.h"

namespace clitest {

/// status: the exit code; 124 = killed at the bound (a hang); 200 = died of a signal.
using Outcome = cubetest::CommandResult;

/// cube_game with `args` (stdout and stderr), `env` before it, killed after `boundSeconds`
/// (coreutils timeout: exit 124).
inline Outcome runCubeGame(const std::string& args, const std::string& env, int boundSeconds) {
    return cubetest::runCommand(env + " timeout -k 5 " + std::to_string(boundSeconds) + " " +
                                    std::string(CUBE_TEST_BIN_DIR) + "/cube_game " + args + " 2>&1",
                                200);
}

/// A command line that must be refused, and what the refusal must mention.
struct RefusedArgs {
    std::string args;
    std::string mention;
};

/// A folder under the temp directory named after the running test (and `prefix`), empty at the
/// start, removed at the end.
class ScratchDir {
public:
    explicit ScratchDir(const std::string& prefix) {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               (prefix + std::string(info->name()) + "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string write(const std::string& name, const std::string& bytes) const {
        std::ofstream(path(name), std::ios::binary) << bytes;
        return path(name);
    }
    std::string fifo(const std::string& name) const {
        EXPECT_EQ(::mkfifo(path(name).c_str(), 0644), 0);
        return path(name);
    }

private:
    std::filesystem::path dir_;
};

}  // namespace clitest
