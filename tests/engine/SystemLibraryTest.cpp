// SystemLibrary (engine_stub/platform/SystemLibrary.h): how a back end opens its system library
// and the messages it gives when it cannot. In process, with a test-only override variable.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "platform/Platform.h"
#include "platform/SystemLibrary.h"

namespace {

const char* const kEnv = "CUBE_TEST_SYSTEM_LIBRARY";

cube::SystemLibraryDesc libcDesc() {
    cube::SystemLibraryDesc desc;
    desc.backend = "test";
    desc.soname = "libc.so.6";
    desc.overrideEnv = kEnv;
    desc.install = "Debian's libc6";
    return desc;
}

/// Sets an environment variable for one scope and restores what was there.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) { had_ = true; old_ = old; }
        ::setenv(name, value, 1);
    }
    ~ScopedEnv() { had_ ? ::setenv(name_, old_.c_str(), 1) : ::unsetenv(name_); }

private:
    const char* name_;
    bool had_ = false;
    std::string old_;
};

}  // namespace

TEST(SystemLibrary, OpensTheSonameAndResolvesAnEntryPoint) {
    ::unsetenv(kEnv);
    cube::SystemLibrary lib;
    std::string error;
    ASSERT_TRUE(lib.open(libcDesc(), &error)) << error;
    EXPECT_EQ(lib.name(), "libc.so.6");
    size_t (*length)(const char*) = nullptr;
    ASSERT_TRUE(lib.resolve("strlen", &length, &error)) << error;
    EXPECT_EQ(length("cube"), 4u);
}

TEST(SystemLibrary, MissingLibraryNamesItTheFlagThePackageAndTheOverride) {
    ScopedEnv env(kEnv, "/nonexistent/libnothing.so.1");
    cube::SystemLibrary lib;
    std::string error;
    EXPECT_FALSE(lib.open(libcDesc(), &error));
    EXPECT_EQ(error.rfind("--backend test: cannot load /nonexistent/libnothing.so.1, named by " +
                              std::string(kEnv) + " (",
                          0),
              0u)
        << error;
    for (const char* part : {"No such file", "install Debian's libc6", "or unset CUBE_TEST_SYSTEM_LIBRARY"})
        EXPECT_NE(error.find(part), std::string::npos) << part << " in: " << error;
}

TEST(SystemLibrary, EmptyOverrideMeansTheSoname) {
    ScopedEnv env(kEnv, "");
    cube::SystemLibrary lib;
    std::string error;
    ASSERT_TRUE(lib.open(libcDesc(), &error)) << error;
    EXPECT_EQ(lib.name(), "libc.so.6");
}

TEST(SystemLibrary, MissingSymbolNamesTheSymbolAndLeavesTheTarget) {
    ::unsetenv(kEnv);
    cube::SystemLibrary lib;
    std::string error;
    ASSERT_TRUE(lib.open(libcDesc(), &error)) << error;
    void (*fn)() = nullptr;
    EXPECT_FALSE(lib.resolve("cubeNoSuchEntryPoint", &fn, &error));
    EXPECT_EQ(fn, nullptr);
    EXPECT_NE(error.find("--backend test: libc.so.6 has no cubeNoSuchEntryPoint"), std::string::npos) << error;
    EXPECT_NE(error.find("Debian's libc6"), std::string::npos) << error;
}

TEST(SystemLibrary, PlatformCreateFailsCleanlyWhenItsBackendIsMissing) {
    struct Case {
        cube::Backend backend;
        const char* env;
        const char* package;
    };
    for (const Case& c : {Case{cube::Backend::OSMesa, "CUBE_OSMESA_LIBRARY", "libosmesa6"},
                          Case{cube::Backend::EGL, "CUBE_EGL_LIBRARY", "libegl1"},
                          Case{cube::Backend::GLFW, "CUBE_GLFW_LIBRARY", "libglfw3"}}) {
        ScopedEnv env(c.env, "/nonexistent/missing.so");
        cube::PlatformDesc desc;
        desc.backend = c.backend;
        desc.width = 16;
        desc.height = 16;
        std::string error;
        EXPECT_EQ(cube::Platform::create(desc, &error), nullptr) << c.env;
        EXPECT_EQ(error.rfind(std::string("--backend ") + cube::backendName(c.backend) + ": cannot load", 0), 0u)
            << error;
        EXPECT_NE(error.find(c.package), std::string::npos) << error;
    }
}
