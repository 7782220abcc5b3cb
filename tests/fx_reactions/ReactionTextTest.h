#pragma once
// What the reaction-validation tests share: load a YAML text as the loader would load a file
// named test.yaml, print what it reported, and check that it reported exactly one thing.
#include <string>

#include <gtest/gtest.h>

#include "../../fx_plugin/reactions/ReactionLoader.h"

namespace reactiontest {

struct Loaded {
    bool ok = false;
    fx::ReactionSet set;
    fx::Diagnostics diags;
};

/// `text` loaded as the file "test.yaml".
inline Loaded loadText(const std::string& text) {
    Loaded r;
    r.ok = fx::loadReactionText(text, "test.yaml", &r.set, &r.diags);
    return r;
}

/// Every diagnostic, one a line (for failure messages).
inline std::string dump(const fx::Diagnostics& d) {
    std::string s;
    for (const auto& x : d) s += x.str() + "\n";
    return s;
}

/// The load failed with exactly one diagnostic, with this code, 1-based line, column (checked
/// only when > 0: where it is unambiguous) and dotted key.
inline void expectOnly(const Loaded& r, fx::ErrorCode code, int line, int column, const std::string& key) {
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.diags.size(), 1u) << dump(r.diags);
    const fx::Diagnostic& d = r.diags[0];
    EXPECT_EQ(d.code, code) << d.str();
    EXPECT_EQ(d.file, "test.yaml");
    EXPECT_EQ(d.line, line) << d.str();
    if (column > 0) {
        EXPECT_EQ(d.column, column) << d.str();
    }
    EXPECT_EQ(d.key, key) << d.str();
}

}  // namespace reactiontest
