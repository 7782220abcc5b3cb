// API 2's C boundary without GL: a host written in C99 (CHostCheck.c, compiled as C) drives the
// plugin through fxGetApi's table alone; and the C++ layer (fx/detail/PluginBridge.h) keeps the
// 1.x behaviour of fxCreatePlugin for C++ hosts.
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "fx/Plugin.h"

extern "C" int fxCHostCheck(const char* reactionFile, const char* badReactionFile, char* report, int capacity);

namespace {

TEST(CApiTest, AHostWrittenInCDrivesThePluginThroughTheTableAlone) {
    const std::string bad = ::testing::TempDir() + "capi_bad_reaction.yaml";
    {
        std::ofstream f(bad);
        f << "reactions:\n  - name: broken\n    particle:\n      drag: fast\n";
    }
    char report[4096];
    const int failed = fxCHostCheck(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", bad.c_str(), report,
                                    int(sizeof report));
    EXPECT_EQ(failed, 0) << report;
}

class CountingHost final : public fx::HostAdapter {
public:
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return 0; }
    fx::WheelContact wheel(int) const override { return {}; }
    void log(fx::LogLevel level, const char* message) override {
        if (level == fx::LogLevel::Error) errors.push_back(message);
    }
    std::vector<std::string> errors;
};

TEST(CApiTest, ACppHostAskingForAnyOneXVersionGetsThePlugin) {
    CountingHost host;
    fx::PluginImports imports;
    imports.host = &host;
    for (uint32_t minor = 0; minor <= 3; ++minor) {
        imports.apiVersion = (1u << 16) | minor;
        fx::ErrorCode code = fx::ErrorCode::InvalidValue;
        EXPECT_NE(fxCreatePlugin(imports, &code), nullptr) << "1." << minor;
        EXPECT_EQ(code, fx::ErrorCode::None);
    }
    imports.apiVersion = (1u << 16) | 4u;  // a 1.x minor that never existed
    fx::ErrorCode code = fx::ErrorCode::None;
    EXPECT_EQ(fxCreatePlugin(imports, &code), nullptr);
    EXPECT_EQ(code, fx::ErrorCode::VersionMismatch);
    ASSERT_EQ(host.errors.size(), 1u);
    EXPECT_NE(host.errors[0].find("error[VersionMismatch] fxCreatePlugin: the host asks for API 1.4"), std::string::npos)
        << host.errors[0];
}

TEST(CApiTest, ErrorNamesComeFromTheLibrarysOneTable) {
    EXPECT_STREQ(fx::errorCodeName(fx::ErrorCode::ShaderBuild), "ShaderBuild");
    EXPECT_STREQ(fx::errorCodeName(fx::ErrorCode::BadDescriptor), "BadDescriptor");
    EXPECT_STREQ(fx::errorCodeName(fx::ErrorCode::UnsupportedDepth), "UnsupportedDepth");
    fx::Diagnostic d;
    d.code = fx::ErrorCode::OutOfRange;
    d.file = "a.yaml";
    d.line = 3;
    d.key = "reactions[0].particle.drag";
    d.message = "expected 0..50";
    EXPECT_EQ(d.str(), "a.yaml:3: error[OutOfRange] reactions[0].particle.drag: expected 0..50");
}

}  // namespace
