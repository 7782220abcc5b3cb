// The loader must never crash, hang or throw, whatever it is given (libFuzzer will hammer
// loadReactionText later; this is a deterministic smoke test of the same promise): every
// prefix of a real file, byte mutations and random bytes. Each call either succeeds with no
// diagnostics or fails with at least one.
#include <fstream>
#include <sstream>
#include <string>

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
    for (const fx::Diagnostic& d : diags) {
        EXPECT_NE(d.code, fx::ErrorCode::None);
        EXPECT_GE(d.line, 0);
        EXPECT_GE(d.column, 0);
    }
}

const std::string kSmoke = std::string(CUBE_SOURCE_DIR) + "/reactions/burnout_smoke.yaml";

TEST(Robustness, EveryPrefixOfARealFile) {
    const std::string text = readFile(kSmoke);
    ASSERT_GT(text.size(), 500u);
    for (size_t n = 0; n <= text.size(); ++n) expectConsistent(text.substr(0, n));
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
