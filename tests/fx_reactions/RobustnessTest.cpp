// The loader must never crash, hang or throw, whatever it is given (libFuzzer will hammer
// loadReactionText later; this is a deterministic smoke test of the same promise): every
// prefix of a real file, byte mutations and random bytes. Each call either succeeds with no
// diagnostics or fails with at least one.
#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../fx_plugin/reactions/ReactionLoader.h"
#include "../../fx_plugin/sim/Rng.h"

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void expectConsistent(const std::string& text) {
    fx::ReactionSet set;
    fx::Diagnostics diags;
    bool ok = false;
    EXPECT_NO_THROW(ok = fx::loadReactionText(text, "fuzz.yaml", &set, &diags));
    EXPECT_EQ(ok, diags.empty()) << text;
    // A diagnostic's line is 1-based, 0 when unknown, and never past the text's last line.
    const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    for (const fx::Diagnostic& d : diags) {
        EXPECT_NE(d.code, fx::ErrorCode::None);
        EXPECT_GE(d.line, 0);
        EXPECT_LE(d.line, lines) << d.message << "\n" << text;
        EXPECT_GE(d.column, 0);
    }
}

const std::string kSmoke = std::string(CUBE_SOURCE_DIR) + "/reactions/burnout_smoke.yaml";

TEST(Robustness, EveryPrefixOfARealFile) {
    const std::string text = readFile(kSmoke);
    ASSERT_GT(text.size(), 500u);
    for (size_t n = 0; n <= text.size(); ++n) expectConsistent(text.substr(0, n));
}

// Where a defect is known, the diagnostic names its line: each numeric value of the real file
// in turn becomes a word, and the first diagnostic points at that line.
TEST(Robustness, ABadValueIsReportedAtItsLine) {
    const std::string text = readFile(kSmoke);
    std::vector<std::string> lines;
    std::stringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    const std::regex number(R"(^(\s+[a-z_]+: )-?[0-9][0-9.]*(\s*(#.*)?)$)");
    int checked = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        if (!std::regex_match(lines[i], m, number)) continue;
        std::string edited;
        for (size_t k = 0; k < lines.size(); ++k) edited += (k == i ? m[1].str() + "fast" + m[2].str() : lines[k]) + "\n";
        fx::ReactionSet set;
        fx::Diagnostics diags;
        EXPECT_FALSE(fx::loadReactionText(edited, "fuzz.yaml", &set, &diags)) << lines[i];
        ASSERT_FALSE(diags.empty()) << lines[i];
        EXPECT_EQ(diags[0].line, int(i) + 1) << lines[i] << ": " << diags[0].message;
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

TEST(Robustness, ByteMutationsOfARealFile) {
    const std::string text = readFile(kSmoke);
    const char kSpecial[] = "[]{}:,-&*!|>'\"%@`#?\t\n .0123456789e";
    fx::Pcg32 rng(1234);
    for (int i = 0; i < 3000; ++i) {
        std::string m = text;
        const int edits = 1 + static_cast<int>(rng.below(4));
        for (int e = 0; e < edits; ++e) {
            const size_t at = rng.below(static_cast<uint32_t>(m.size()));
            switch (rng.below(4)) {
            case 0: m[at] = kSpecial[rng.below(sizeof kSpecial - 1)]; break;
            case 1: m.erase(at, 1 + rng.below(8)); break;
            case 2: m.insert(at, 1, kSpecial[rng.below(sizeof kSpecial - 1)]); break;
            default: m[at] = static_cast<char>(rng.below(256)); break;
            }
        }
        expectConsistent(m);
    }
}

TEST(Robustness, RandomBytesAndRandomYamlTokens) {
    fx::Pcg32 rng(99);
    const char* kTokens[] = {"reactions:", "\n", "  ", "- ", "[", "]", "{", "}", ": ", ", ",
                             "&a ", "*a", "name", "type", "dust", ".nan", "-1", "1e9", "'",
                             "\"", "? ", "!!str ", "|\n", "---\n", "particle", "drag", "#"};
    for (int i = 0; i < 2000; ++i) {
        std::string s;
        const int n = static_cast<int>(rng.below(64));
        if (i % 2 == 0) {
            for (int k = 0; k < n; ++k) s += static_cast<char>(rng.below(256));
        } else {
            for (int k = 0; k < n; ++k) s += kTokens[rng.below(sizeof kTokens / sizeof kTokens[0])];
        }
        expectConsistent(s);
    }
}

}  // namespace
