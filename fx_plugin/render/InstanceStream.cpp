#include "InstanceStream.h"

#include <cstring>

#include "render/PrivateGl.h"

namespace fx {
namespace {

constexpr size_t kMinCapacityBytes = 256 * sizeof(ParticleInstance);
constexpr GLuint kCornerAttrib = 0, kPosSizeAttrib = 1, kLifeRotFadeFrameAttrib = 2;

}  // namespace

bool writeMapped(uint32_t target, size_t bytes, const std::function<void(void*)>& write) {
    void* mapped = glMapBufferRange(GLenum(target), 0, GLsizeiptr(bytes), GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
    if (!mapped) {
        glGetError();  // the refusal this call raised (out of memory): taken back, as documented
        return false;
    }
    write(mapped);
    // False: the store was lost while mapped (GL says it may be, on a display change); the caller
    // fills it again.
    return glUnmapBuffer(GLenum(target)) == GL_TRUE;
}

bool copyMappedInPieces(uint32_t target, const void* data, size_t bytes, const Jobs& jobs) {
    const Pieces pieces = splitWork(bytes, 512 * 1024, 16);
    if (!jobs.parallel() || pieces.count <= 1) return false;
    return writeMapped(target, bytes, [&](void* mapped) {
        jobs.run(pieces, [&](uint32_t piece) {
            const size_t first = pieces.begin(piece);
            std::memcpy(static_cast<char*>(mapped) + first, static_cast<const char*>(data) + first,
                        pieces.end(piece) - first);
        });
    });
}

InstanceStream::~InstanceStream() {
    if (instanceBuffer_) glDeleteBuffers(1, &instanceBuffer_);
    if (cornerBuffer_) glDeleteBuffers(1, &cornerBuffer_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
}

void InstanceStream::create() {
    if (vao_) return;
    // Triangle-strip order: bottom-left, bottom-right, top-left, top-right; padded to the eight
    // vertices a trimmed fan draws (which takes its corners from a uniform table instead).
    static const float kCorners[16] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f,
                                       1.0f,  1.0f,  1.0f, 1.0f,  1.0f,  1.0f, 1.0f, 1.0f};
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &cornerBuffer_);
    glGenBuffers(1, &instanceBuffer_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, cornerBuffer_);
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(kCornerAttrib);
    glVertexAttribPointer(kCornerAttrib, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    capacityBytes_ = kMinCapacityBytes;
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacityBytes_), nullptr, GL_STREAM_DRAW);
    glEnableVertexAttribArray(kPosSizeAttrib);
    glEnableVertexAttribArray(kLifeRotFadeFrameAttrib);
    glVertexAttribDivisor(kPosSizeAttrib, 1);
    glVertexAttribDivisor(kLifeRotFadeFrameAttrib, 1);
    bindRange(0);
}

void InstanceStream::upload(const ParticleInstance* data, int count, const Jobs& jobs) {
    const size_t n = size_t(count > 0 ? count : 0);
    const size_t bytes = n * sizeof(ParticleInstance);
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    if (bytes > capacityBytes_) {
        while (capacityBytes_ < bytes) capacityBytes_ *= 2;
        ++growCount_;
    }
    // Orphan: a fresh store of the same size; draws still queued keep reading the old one.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacityBytes_), nullptr, GL_STREAM_DRAW);
    if (!bytes) return;
    if (copyMappedInPieces(GL_ARRAY_BUFFER, data, bytes, jobs)) {
        ++mappedUploads_;
        return;
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), data);
}

void InstanceStream::bindRange(int first) {
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    const size_t base = size_t(first) * sizeof(ParticleInstance);
    glVertexAttribPointer(kPosSizeAttrib, 4, GL_FLOAT, GL_FALSE, sizeof(ParticleInstance),
                          reinterpret_cast<const void*>(base));
    glVertexAttribPointer(kLifeRotFadeFrameAttrib, 4, GL_FLOAT, GL_FALSE, sizeof(ParticleInstance),
                          reinterpret_cast<const void*>(base + 4 * sizeof(float)));
}

}  // namespace fx
