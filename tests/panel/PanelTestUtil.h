#pragma once
// Helpers for the tweak panel's tests: a private copy of the shipped reaction files (edits and
// saves never touch reactions/), and a small headless game that loads it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "../engine/GameTestUtil.h"
#include "RunCommand.h"
#include "game/Game.h"
#include "gl/Paths.h"

namespace paneltest {

namespace fs = std::filesystem;

using cubetest::readFile;

inline void writeFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

/// A fresh folder with copies of reactions/*.yaml, removed on destruction.
class ReactionCopy {
public:
    ReactionCopy() {
        const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = (fs::temp_directory_path() / ("cube_panel_" + std::string(t->test_suite_name()) + "_" + t->name() +
                                             "_" + std::to_string(::getpid())))
                   .string();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        for (const auto& e : fs::directory_iterator(cube::paths::reactions())) {
            if (e.path().extension() == ".yaml") fs::copy_file(e.path(), fs::path(dir_) / e.path().filename());
        }
    }
    ~ReactionCopy() { fs::remove_all(dir_); }
    const std::string& dir() const { return dir_; }
    std::string file(const std::string& name) const { return dir_ + "/" + name; }

private:
    std::string dir_;
};

/// Options for a headless run over `reactions`: fixed dt, seed 7, no HUD.
inline cube::Options options(const std::string& reactions, int w = 320, int h = 256) {
    cube::Options o = cubetest::smallOptions(w, h);
    o.reactions = reactions;
    return o;
}

/// The plugin's index of reaction `name`, or -1.
inline int reactionIndex(fx::Plugin& plugin, const std::string& name) {
    for (int i = 0; i < plugin.reactionCount(); ++i)
        if (plugin.reactionName(i) == name) return i;
    return -1;
}

}  // namespace paneltest
