// Platform back ends are loaded on demand (engine_stub/platform/SystemLibrary.h): no program
// links libOSMesa, libEGL or libglfw, a run loads only the one its --backend names, and a
// missing one is an exit-1 error naming the library, the flag and the Debian package.
// CUBE_OSMESA_LIBRARY / CUBE_EGL_LIBRARY / CUBE_GLFW_LIBRARY stand in for an uninstalled package.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "RunCommand.h"

// Named so that the test files of one unity translation unit keep their helpers apart.
namespace platform_loading_test {
namespace {

using Result = cubetest::CommandResult;

Result run(const std::string& cmd) { return cubetest::runCommand(cmd + " 2>&1", 128); }

std::string bin(const std::string& name) { return std::string(CUBE_TEST_BIN_DIR) + "/" + name; }

Result runGame(const std::string& args, const std::string& env = "") {
    return run(env + " " + bin("cube_game") + " " + args);
}

bool exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

std::string slurp(const std::string& path) { return cubetest::readFile(path); }

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

std::string tmp(const std::string& name) { return "/tmp/cube_platform_" + std::to_string(::getpid()) + "_" + name; }

// As in CliTest.cpp: Mesa's EGL path unloads a DRI driver at exit, which LeakSanitizer cannot
// attribute; leak checks are off for EGL runs under the sanitizer stage.
const std::string kDriverLeaksOff = "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\"";
const std::string kMissing = "/nonexistent/cube_platform_test/missing.so";
const std::string kFrame = " --frames 3 --size 128x96 --fixed-dt 0.0166667 --mode soft ";

// Libraries no product binary may depend on: the three back ends and the GL dispatchers that
// would drag a vendor driver in with them.
const char* const kBackendLibraries[] = {"libOSMesa", "libEGL", "libglfw", "libGL.", "libGLX", "libOpenGL"};

}  // namespace

TEST(PlatformLoading, MissingOSMesaNamesLibraryFlagAndPackageOnceAndExitsOne) {
    const Result r = runGame("--frames 1 --size 64x64", "CUBE_OSMESA_LIBRARY=" + kMissing);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_EQ(count(r.output, "cube_game: --backend osmesa: cannot load " + kMissing), 1u) << r.output;
    for (const char* part : {"named by CUBE_OSMESA_LIBRARY", "No such file", "install Debian's libosmesa6"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << " in: " << r.output;
    EXPECT_EQ(r.output.find("frames"), std::string::npos) << "no frame may run: " << r.output;
}

TEST(PlatformLoading, LibraryWithoutTheEntryPointsNamesTheMissingSymbol) {
    // libc loads fine but exports no OSMesa: the first entry point looked up is reported.
    const Result r = runGame("--frames 1 --size 64x64", "CUBE_OSMESA_LIBRARY=libc.so.6");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_EQ(count(r.output, "cube_game: --backend osmesa: libc.so.6"), 1u) << r.output;
    for (const char* part : {"has no OSMesaCreateContextAttribs", "libosmesa6"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << " in: " << r.output;
}

TEST(PlatformLoading, MissingEGLNamesLibEGLAndAVendorDriver) {
    const Result r = runGame("--backend egl --frames 1 --size 64x64", "CUBE_EGL_LIBRARY=" + kMissing);
    EXPECT_EQ(r.status, 1) << r.output;
    for (const char* part : {"--backend egl: cannot load", "libegl1", "libegl-mesa0"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << " in: " << r.output;
}

TEST(PlatformLoading, MissingGLFWNamesLibglfw3) {
    // No display is needed to get this far: the library is loaded before glfwInit.
    const Result r = runGame("--window --frames 1 --size 64x64", "CUBE_GLFW_LIBRARY=" + kMissing);
    EXPECT_EQ(r.status, 1) << r.output;
    for (const char* part : {"--backend glfw: cannot load", "libglfw3"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << " in: " << r.output;
}

TEST(PlatformLoading, EglRendersAFrameWithOSMesaMissing) {
    const std::string png = tmp("egl_no_osmesa.png");
    const Result r = runGame("--backend egl" + kFrame + "--screenshot " + png,
                             kDriverLeaksOff + " CUBE_OSMESA_LIBRARY=" + kMissing);
    if (r.status != 0) {
        // No EGL driver on this machine: that must be what it says, not anything about OSMesa.
        EXPECT_EQ(r.status, 1);
        EXPECT_EQ(r.output.find("osmesa"), std::string::npos) << r.output;
        GTEST_SKIP() << "no EGL platform here: " << r.output;
    }
    EXPECT_GT(slurp(png).size(), 500u) << r.output;
    std::remove(png.c_str());
}

TEST(PlatformLoading, EglRunNeverLoadsLibOSMesa) {
    // The loader's own record of every object it maps: libOSMesa (and, with it, the rest of
    // the software-renderer stack it needs) must not be among them.
    const Result r = runGame("--backend egl --frames 1 --size 64x64", kDriverLeaksOff + " LD_DEBUG=files");
    if (r.output.find("egl on ") == std::string::npos) GTEST_SKIP() << "no EGL platform here";
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("libEGL.so.1"), std::string::npos) << "LD_DEBUG=files gave no loader trace";
    EXPECT_EQ(r.output.find("libOSMesa"), std::string::npos) << "an EGL run mapped libOSMesa";
}

TEST(PlatformLoading, OSMesaRunNeverLoadsEGLOrGLFW) {
    const Result r = runGame("--frames 1 --size 64x64", "LD_DEBUG=files");
    ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find("libOSMesa.so.8"), std::string::npos) << "LD_DEBUG=files gave no loader trace";
    for (const char* lib : {"libEGL", "libglfw"})
        EXPECT_EQ(r.output.find(lib), std::string::npos) << "an OSMesa run mapped " << lib;
}

TEST(PlatformLoading, ProductBinariesNeedNoBackendLibrary) {
    if (run("command -v readelf").status != 0) GTEST_SKIP() << "readelf (binutils) not installed";
    for (const char* program : {"cube_game", "fxbench"}) {
        const std::string path = bin(program);
        if (!exists(path)) {
            EXPECT_STRNE(program, "cube_game") << "cube_game not built";
            continue;
        }
        // Direct dependencies (readelf -d: NEEDED) and everything they bring in (ldd).
        const Result needed = run("readelf -d " + path + " | grep NEEDED");
        ASSERT_EQ(needed.status, 0) << needed.output;
        ASSERT_NE(needed.output.find("libc.so"), std::string::npos) << needed.output;
        const Result ldd = run("ldd " + path);
        ASSERT_EQ(ldd.status, 0) << ldd.output;
        for (const char* lib : kBackendLibraries) {
            EXPECT_EQ(needed.output.find(lib), std::string::npos) << program << " NEEDs " << lib << ":\n" << needed.output;
            EXPECT_EQ(ldd.output.find(lib), std::string::npos) << program << " loads " << lib << ":\n" << ldd.output;
        }
    }
}
}  // namespace platform_loading_test
