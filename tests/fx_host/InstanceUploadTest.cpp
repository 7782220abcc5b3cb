// InstanceStream::upload with the host's job system: a list of tens of thousands of instances is
// copied into the mapped buffer in pieces on the host's threads, and the buffer then holds exactly
// what glBufferSubData puts there; short lists and hosts without one take glBufferSubData.
#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include "FxTestHost.h"
#include "render/GlStateGuard.h"
#include "render/InstanceStream.h"

namespace fxtest {
namespace instance_upload_test {  // named: the fx_host tests build as unity batches

// Runs the pieces on three threads and counts the calls.
class ThreadedHost final : public fx::HostAdapter {
public:
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return 0; }
    fx::WheelContact wheel(int) const override { return fx::WheelContact{}; }
    void log(fx::LogLevel, const char*) override {}
    void parallelFor(uint32_t count, Task task, void* data) override {
        ++calls;
        std::atomic<uint32_t> next{0};
        std::vector<std::thread> threads;
        for (int t = 0; t < 3; ++t) {
            threads.emplace_back([&]() {
                for (uint32_t i; (i = next.fetch_add(1)) < count;) task(data, i);
            });
        }
        for (std::thread& t : threads) t.join();
    }
    int calls = 0;
};

std::vector<fx::ParticleInstance> instances(int n, float salt) {
    std::vector<fx::ParticleInstance> v(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        fx::ParticleInstance& p = v[size_t(i)];
        p.x = float(i) * 0.5f + salt;
        p.y = float(i % 97);
        p.z = -float(i % 1013) - salt;
        p.size = 0.25f + float(i % 7);
        p.life = float(i % 100) / 100.0f;
        p.rotation = float(i % 13) - salt;
        p.fade = float(i % 10) / 10.0f;
        p.frame = float(i & 3);
    }
    return v;
}

// The first `n` instances the stream's buffer holds (GL_ARRAY_BUFFER is bound to it by upload).
std::vector<fx::ParticleInstance> readBack(int n) {
    std::vector<fx::ParticleInstance> out(static_cast<size_t>(n));
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(size_t(n) * sizeof(fx::ParticleInstance)), out.data());
    return out;
}

bool same(const std::vector<fx::ParticleInstance>& a, const std::vector<fx::ParticleInstance>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(fx::ParticleInstance)) == 0;
}

class InstanceUploadTest : public FxHostTest {};

TEST_F(InstanceUploadTest, ALongListIsCopiedInPiecesIntoTheMappedBufferAndReadsBackExactly) {
    ThreadedHost host;
    const fx::Jobs jobs(&host);
    fx::GlStateGuard guard;
    fx::InstanceStream stream;
    stream.create();

    const std::vector<fx::ParticleInstance> big = instances(70000, 0.0f);  // 4 pieces of 16k and more
    stream.upload(big.data(), int(big.size()), jobs);
    EXPECT_EQ(stream.mappedUploads(), 1);
    EXPECT_GT(host.calls, 0);
    EXPECT_TRUE(same(readBack(int(big.size())), big));

    // Shorter than two pieces: glBufferSubData, with no call into the host.
    const int callsBefore = host.calls;
    const std::vector<fx::ParticleInstance> small = instances(20000, 3.0f);
    stream.upload(small.data(), int(small.size()), jobs);
    EXPECT_EQ(stream.mappedUploads(), 1);
    EXPECT_EQ(host.calls, callsBefore);
    EXPECT_TRUE(same(readBack(int(small.size())), small));

    // No job system: glBufferSubData whatever the length; the same bytes.
    const std::vector<fx::ParticleInstance> other = instances(70000, 7.0f);
    stream.upload(other.data(), int(other.size()), fx::Jobs());
    EXPECT_EQ(stream.mappedUploads(), 1);
    EXPECT_TRUE(same(readBack(int(other.size())), other));

    // Mapped again once warm (the buffer does not grow): still exact.
    stream.upload(big.data(), int(big.size()), jobs);
    EXPECT_EQ(stream.mappedUploads(), 2);
    EXPECT_TRUE(same(readBack(int(big.size())), big));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace instance_upload_test
}  // namespace fxtest
