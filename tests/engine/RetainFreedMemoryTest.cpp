// cube::retainFreedMemory (platform/Platform.h): after it, a block of several MiB comes from the
// heap and stays there when freed, instead of a fresh mmap that the next frame page-faults in
// again. Each test runs in its own process (gtest_discover_tests), so malloc starts at its
// defaults: a 128 KiB mmap threshold that only grows to the size of blocks freed so far.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "platform/Platform.h"

#ifdef __GLIBC__
#include <malloc.h>

namespace {

// Blocks malloc currently holds as separate mmaps.
size_t mappedBlocks() { return mallinfo2().hblks; }

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kOwnAllocator = true;  // AddressSanitizer replaces malloc: nothing to observe
#else
constexpr bool kOwnAllocator = false;
#endif

// True when a `bytes` block is served by its own mmap (touched, so it is really in use).
bool servedByMmap(size_t bytes) {
    const size_t before = mappedBlocks();
    void* p = std::malloc(bytes);
    EXPECT_NE(p, nullptr);
    std::memset(p, 1, bytes);
    const bool mapped = mappedBlocks() > before;
    std::free(p);
    return mapped;
}

TEST(RetainFreedMemory, LargeBlocksComeFromTheHeapAfterwards) {
    if (kOwnAllocator) GTEST_SKIP() << "AddressSanitizer's allocator has no glibc thresholds";
    // Control: with the defaults an 8 MiB block is its own mmap, returned to the kernel on free.
    EXPECT_TRUE(servedByMmap(8u << 20)) << "malloc's defaults changed: this test no longer tells anything";
    cube::retainFreedMemory();
    EXPECT_FALSE(servedByMmap(8u << 20));
    EXPECT_FALSE(servedByMmap(24u << 20));
}

TEST(RetainFreedMemory, ASoftwareRendererPlatformAppliesIt) {
    if (kOwnAllocator) GTEST_SKIP() << "AddressSanitizer's allocator has no glibc thresholds";
    cube::PlatformDesc desc;
    desc.width = 64;
    desc.height = 64;
    std::string error;
    std::unique_ptr<cube::Platform> platform = cube::Platform::create(desc, &error);
    ASSERT_TRUE(platform) << error;
    ASSERT_TRUE(platform->softwareRenderer()) << platform->rendererName();
    // 24 MiB: larger than anything llvmpipe frees while it starts, so the dynamic threshold
    // alone would still map it.
    EXPECT_FALSE(servedByMmap(24u << 20));
}

}  // namespace
#endif
