// File and directory loading: missing paths, oversized files, and a directory reporting the
// errors of every file plus the rules that span files (unique names).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "../../fx_plugin/reactions/ReactionLoader.h"

namespace fs = std::filesystem;

namespace {

class TempDir {
public:
    TempDir() {
        path_ = fs::temp_directory_path() /
                ("fx_loader_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path p = path_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::string str() const { return path_.string(); }

private:
    static inline int counter_ = 0;
    fs::path path_;
};

TEST(LoaderFiles, MissingFileIsFileNotFound) {
    fx::Diagnostics diags;
    fx::ReactionSet set;
    EXPECT_FALSE(fx::loadReactionFile("/nonexistent/nowhere.yaml", &set, &diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::FileNotFound);
    EXPECT_EQ(diags[0].file, "/nonexistent/nowhere.yaml");
}

TEST(LoaderFiles, OversizedFileIsRefusedBeforeParsing) {
    TempDir dir;
    const std::string path = dir.write("big.yaml", std::string(fx::kMaxFileBytes + 1, '#'));
    fx::Diagnostics diags;
    EXPECT_FALSE(fx::loadReactionFile(path, nullptr, &diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::FileTooLarge);
}

TEST(LoaderFiles, DirectoryReportsErrorsFromEveryFile) {
    TempDir dir;
    dir.write("a.yaml", "reactions:\n  - name: a\n    type: dust\n    particle: {drag: fast}\n");
    dir.write("b.yaml", "reactions:\n  - name: b\n    type: mist\n");
    dir.write("c.yaml", "reactions:\n  - name: c\n    type: dust\n");
    dir.write("notes.txt", "not yaml: [");  // not a .yaml file: ignored
    fx::ReactionSet set;
    set.reactions.resize(3);
    fx::Diagnostics diags;
    EXPECT_FALSE(fx::loadReactionDirectory(dir.str(), &set, &diags));
    ASSERT_EQ(diags.size(), 2u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::WrongType);
    EXPECT_EQ(fs::path(diags[0].file).filename(), "a.yaml");
    EXPECT_EQ(diags[1].code, fx::ErrorCode::InvalidEnum);
    EXPECT_EQ(fs::path(diags[1].file).filename(), "b.yaml");
    EXPECT_EQ(set.reactions.size(), 3u);  // untouched
}

TEST(LoaderFiles, DuplicateNamesAcrossFiles) {
    TempDir dir;
    dir.write("a.yaml", "reactions:\n  - name: smoke\n    type: dust\n");
    dir.write("b.yaml", "reactions:\n  - name: other\n    type: dust\n  - name: smoke\n    type: dust\n");
    fx::Diagnostics diags;
    EXPECT_FALSE(fx::loadReactionDirectory(dir.str(), nullptr, &diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::DuplicateName);
    EXPECT_EQ(fs::path(diags[0].file).filename(), "b.yaml");
    EXPECT_EQ(diags[0].line, 4);
    EXPECT_EQ(diags[0].key, "reactions[1].name");
}

TEST(LoaderFiles, DirectoryInSortedOrderAndPathDispatch) {
    TempDir dir;
    dir.write("z.yaml", "reactions:\n  - {name: z, type: dust}\n");
    dir.write("a.yaml", "reactions:\n  - {name: a, type: dust}\n");
    fx::ReactionSet set;
    fx::Diagnostics diags;
    ASSERT_TRUE(fx::loadReactionPath(dir.str(), &set, &diags));
    ASSERT_EQ(set.reactions.size(), 2u);
    EXPECT_EQ(set.reactions[0].name, "a");
    EXPECT_EQ(set.reactions[1].name, "z");
    ASSERT_TRUE(fx::loadReactionPath(dir.str() + "/z.yaml", &set, &diags));
    ASSERT_EQ(set.reactions.size(), 1u);
    EXPECT_EQ(set.reactions[0].name, "z");
}

TEST(LoaderFiles, DirectoryWithoutYamlIsFileNotFound) {
    TempDir dir;
    fx::Diagnostics diags;
    EXPECT_FALSE(fx::loadReactionDirectory(dir.str(), nullptr, &diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::FileNotFound);
}

}  // namespace
