// Hot reload through ReactionLibrary: a bad edit is reported once and the running set stays;
// fixing it makes the new values live; added/removed files and same-mtime edits are noticed.
// Polls like a game does (every ~16 ms) with a deadline of 1.5 s; nothing asserts a duration.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <unistd.h>

#include "../../fx_plugin/reactions/ReactionLibrary.h"

namespace fs = std::filesystem;
using fx::ReactionLibrary;
using Poll = fx::ReactionLibrary::PollResult;

namespace {

class HotReload : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("fx_hotreload_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        lib_.setPollInterval(0.0);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
        return p.string();
    }
    static std::string reaction(const std::string& name, const std::string& drag) {
        return "reactions:\n  - name: " + name + "\n    type: wheel_smoke\n    particle:\n      drag: " +
               drag + "\n";
    }
    // Polls every frame (16 ms) until something other than Unchanged comes back, for 1.5 s.
    Poll pollUntilChange(fx::Diagnostics* diags) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
        while (std::chrono::steady_clock::now() < deadline) {
            Poll r = lib_.poll(diags);
            if (r != Poll::Unchanged) return r;
            std::this_thread::sleep_for(std::chrono::milliseconds(16));
        }
        return Poll::Unchanged;
    }
    float drag(size_t i = 0) const { return lib_.current().reactions.at(i).particle.drag; }

    fs::path dir_;
    ReactionLibrary lib_;
};

TEST_F(HotReload, BadEditKeepsTheRunningSetAndAFixGoesLive) {
    write("smoke.yaml", reaction("smoke", "1.0"));
    fx::Diagnostics diags;
    ASSERT_TRUE(lib_.load(dir_.string(), &diags));
    ASSERT_TRUE(diags.empty());
    EXPECT_EQ(drag(), 1.0f);
    EXPECT_EQ(lib_.generation(), 1);

    write("smoke.yaml", reaction("smoke", "fast"));
    EXPECT_EQ(pollUntilChange(&diags), Poll::Rejected);
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::WrongType);
    EXPECT_EQ(diags[0].line, 5);
    EXPECT_EQ(diags[0].key, "reactions[0].particle.drag");
    EXPECT_EQ(drag(), 1.0f);  // the old value is still live
    EXPECT_EQ(lib_.generation(), 1);

    // The same bad content is not reported again every frame.
    fx::Diagnostics again;
    for (int i = 0; i < 5; ++i) EXPECT_EQ(lib_.poll(&again), Poll::Unchanged);
    EXPECT_TRUE(again.empty());

    write("smoke.yaml", reaction("smoke", "2.5"));
    fx::Diagnostics none;
    EXPECT_EQ(pollUntilChange(&none), Poll::Reloaded);
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(drag(), 2.5f);
    EXPECT_EQ(lib_.generation(), 2);
}

TEST_F(HotReload, EditWithinOneMtimeTickIsSeenByContentHash) {
    const std::string path = write("smoke.yaml", reaction("smoke", "1.5"));
    ASSERT_TRUE(lib_.load(dir_.string(), nullptr));
    const auto stamp = fs::last_write_time(path);
    // Same size, same mtime: only the bytes differ.
    write("smoke.yaml", reaction("smoke", "2.5"));
    fs::last_write_time(path, stamp);
    EXPECT_EQ(pollUntilChange(nullptr), Poll::Reloaded);
    EXPECT_EQ(drag(), 2.5f);
}

TEST_F(HotReload, TouchWithoutChangeIsNotAReload) {
    const std::string path = write("smoke.yaml", reaction("smoke", "1.5"));
    ASSERT_TRUE(lib_.load(dir_.string(), nullptr));
    fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(5));
    EXPECT_EQ(lib_.poll(nullptr), Poll::Unchanged);
    EXPECT_EQ(lib_.generation(), 1);
}

TEST_F(HotReload, AddedAndRemovedFilesAreNoticed) {
    write("a.yaml", reaction("a", "1.0"));
    ASSERT_TRUE(lib_.load(dir_.string(), nullptr));
    ASSERT_EQ(lib_.current().reactions.size(), 1u);

    write("b.yaml", reaction("b", "3.0"));
    EXPECT_EQ(pollUntilChange(nullptr), Poll::Reloaded);
    ASSERT_EQ(lib_.current().reactions.size(), 2u);
    EXPECT_EQ(drag(1), 3.0f);

    fs::remove(dir_ / "a.yaml");
    EXPECT_EQ(pollUntilChange(nullptr), Poll::Reloaded);
    ASSERT_EQ(lib_.current().reactions.size(), 1u);
    EXPECT_EQ(lib_.current().reactions[0].name, "b");

    // A new file that clashes with a running name is rejected as a whole.
    write("c.yaml", reaction("b", "4.0"));
    fx::Diagnostics diags;
    EXPECT_EQ(pollUntilChange(&diags), Poll::Rejected);
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::DuplicateName);
    EXPECT_EQ(drag(), 3.0f);
}

TEST_F(HotReload, WatchedFileRemovedThenRestored) {
    const std::string path = write("smoke.yaml", reaction("smoke", "1.0"));
    ASSERT_TRUE(lib_.load(path, nullptr));
    fs::remove(path);
    fx::Diagnostics diags;
    EXPECT_EQ(pollUntilChange(&diags), Poll::Rejected);
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::FileNotFound);
    EXPECT_EQ(drag(), 1.0f);

    write("smoke.yaml", reaction("smoke", "0.5"));
    EXPECT_EQ(pollUntilChange(nullptr), Poll::Reloaded);
    EXPECT_EQ(drag(), 0.5f);
}

TEST_F(HotReload, FailedLoadKeepsTheWatchedSet) {
    write("smoke.yaml", reaction("smoke", "1.0"));
    ASSERT_TRUE(lib_.load(dir_.string(), nullptr));
    fx::Diagnostics diags;
    EXPECT_FALSE(lib_.load((dir_ / "missing.yaml").string(), &diags));
    EXPECT_EQ(diags.size(), 1u);
    EXPECT_EQ(lib_.path(), dir_.string());
    EXPECT_EQ(drag(), 1.0f);
}

TEST_F(HotReload, NothingToPollBeforeALoad) {
    EXPECT_EQ(lib_.poll(nullptr), Poll::Unchanged);
    EXPECT_FALSE(lib_.loaded());
}

}  // namespace
