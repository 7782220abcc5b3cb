#pragma once
// What the reaction-validation tests share: load a YAML text as the loader would load a file
// named test.yaml, print what it reported, and check that it reported exactly one thing.
#include <ostream>
#include <string>
#include <vector>

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

/// One diagnostic a test expects: its code and, where given, its dotted key (nullptr: not
/// checked; "" is checked), 1-based line and column (0: not checked).
struct Expected {
    fx::ErrorCode code;
    const char* key = nullptr;
    int line = 0;
    int column = 0;
};

/// The load failed with exactly these diagnostics, in this order.
inline void expectDiagnostics(const Loaded& r, const std::vector<Expected>& want) {
    EXPECT_FALSE(r.ok);
    ASSERT_EQ(r.diags.size(), want.size()) << dump(r.diags);
    for (size_t i = 0; i < want.size(); ++i) {
        const fx::Diagnostic& d = r.diags[i];
        EXPECT_EQ(d.code, want[i].code) << d.str();
        if (want[i].key) {
            EXPECT_EQ(d.key, want[i].key) << d.str();
        }
        if (want[i].line > 0) {
            EXPECT_EQ(d.line, want[i].line) << d.str();
        }
        if (want[i].column > 0) {
            EXPECT_EQ(d.column, want[i].column) << d.str();
        }
    }
}

/// A text the loader refuses with exactly one diagnostic (as expectOnly checks it), whose
/// message, where `mentions` is set, contains that text. A row of a table-driven test.
struct Rejected {
    const char* name;  ///< the test's name
    std::string text;  ///< the whole file
    fx::ErrorCode code;
    int line;
    int column;  ///< 0: not checked
    const char* key;
    const char* mentions = nullptr;
};

inline void expectRejected(const Rejected& c) {
    const Loaded r = loadText(c.text);
    expectOnly(r, c.code, c.line, c.column, c.key);
    if (c.mentions && r.diags.size() == 1) {
        EXPECT_NE(r.diags[0].message.find(c.mentions), std::string::npos) << r.diags[0].message;
    }
}

/// gtest names a case by its name (not its bytes) in listings and failures.
inline void PrintTo(const Rejected& c, std::ostream* os) { *os << c.name; }
inline std::string rejectedName(const ::testing::TestParamInfo<Rejected>& info) { return info.param.name; }

}  // namespace reactiontest
