#pragma once
// Checks by pass name that cannot pass vacuously: each fails when no pass of that name was
// declared, so renaming a pass breaks the tests that name it instead of silently satisfying
// EXPECT_FALSE(isKept(...)).
#include <gtest/gtest.h>

#include <string>

#include "rtt/FrameGraph.h"

inline ::testing::AssertionResult passKept(const cube::rtt::FrameGraph& graph, const char* name) {
    if (!graph.declared(name)) return ::testing::AssertionFailure() << "no pass named '" << name << "' was declared";
    if (!graph.isKept(name)) return ::testing::AssertionFailure() << "pass '" << name << "' was culled";
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult passCulled(const cube::rtt::FrameGraph& graph, const char* name) {
    if (!graph.declared(name)) return ::testing::AssertionFailure() << "no pass named '" << name << "' was declared";
    if (graph.isKept(name)) return ::testing::AssertionFailure() << "pass '" << name << "' was kept";
    return ::testing::AssertionSuccess();
}

/// For a pass the frame may leave out altogether (the engine declares some passes only when
/// needed): neither kept nor run, declared or not. It cannot catch a rename on its own: a test
/// that uses it also checks passKept() of the same name in a frame that needs the pass.
inline ::testing::AssertionResult passNotRun(const cube::rtt::FrameGraph& graph, const char* name) {
    if (graph.isKept(name)) return ::testing::AssertionFailure() << "pass '" << name << "' was kept";
    for (const std::string& executed : graph.report().executed)
        if (executed == name) return ::testing::AssertionFailure() << "pass '" << name << "' ran";
    return ::testing::AssertionSuccess();
}
