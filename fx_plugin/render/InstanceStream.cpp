#include "InstanceStream.h"

#include "render/PrivateGl.h"

namespace fx {
namespace {

constexpr size_t kMinCapacityBytes = 256 * sizeof(ParticleInstance);
constexpr GLuint kCornerAttrib = 0, kPosSizeAttrib = 1, kLifeRotFadeFrameAttrib = 2;

}  // namespace

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

void InstanceStream::upload(const ParticleInstance* data, int count) {
    const size_t bytes = size_t(count > 0 ? count : 0) * sizeof(ParticleInstance);
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    if (bytes > capacityBytes_) {
        while (capacityBytes_ < bytes) capacityBytes_ *= 2;
        ++growCount_;
    }
    // Orphan: a fresh store of the same size; draws still queued keep reading the old one.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacityBytes_), nullptr, GL_STREAM_DRAW);
    if (bytes) glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(bytes), data);
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
