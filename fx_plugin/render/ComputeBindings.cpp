#include "ComputeBindings.h"

#include "DrawList.h"
#include "InstanceStream.h"
#include "TileSort.h"
#include "render/PrivateGl.h"

namespace fx {

static_assert(TileSort::kBindings <= ComputeBindingsScope::kBindings, "the sort's bindings are put back too");

ComputeBindingsScope::ComputeBindingsScope() {
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &generic_);
    for (int i = 0; i < kBindings; ++i) {
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, GLuint(i), &buffer_[i]);
        GLint64 v = 0;
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, GLuint(i), &v);
        start_[i] = v;
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, GLuint(i), &v);
        size_[i] = v;
    }
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, kImage, &image_[0]);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, kImage, &image_[1]);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, kImage, &image_[2]);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, kImage, &image_[3]);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, kImage, &image_[4]);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, kImage, &image_[5]);
}

ComputeBindingsScope::~ComputeBindingsScope() {
    glBindImageTexture(kImage, GLuint(image_[0]), image_[1], GLboolean(image_[2]), image_[3], GLenum(image_[4]),
                       GLenum(image_[5]));
    for (int i = 0; i < kBindings; ++i) {
        if (buffer_[i] != 0 && size_[i] > 0) {
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, GLuint(i), GLuint(buffer_[i]), GLintptr(start_[i]),
                              GLsizeiptr(size_[i]));
        } else {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(i), GLuint(buffer_[i]));
        }
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(generic_));
}

void fillStorage(uint32_t* buffer, size_t* capacity, const void* data, size_t bytes, const Jobs& jobs) {
    TileSort::ensureBuffer(buffer, capacity, bytes);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer);
    if (bytes > 0 && !copyMappedInPieces(GL_SHADER_STORAGE_BUFFER, data, bytes, jobs)) {
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(bytes), data);
    }
}

bool fillInstances(uint32_t* buffer, size_t* capacity, DrawList& list, const Jobs& jobs) {
    const size_t bytes = size_t(list.particleCount()) * sizeof(ParticleInstance);
    if (list.gatherPending()) {
        TileSort::ensureBuffer(buffer, capacity, bytes);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer);
        if (writeMapped(GL_SHADER_STORAGE_BUFFER, bytes,
                        [&](void* mapped) { list.gatherInto(static_cast<ParticleInstance*>(mapped), jobs); })) {
            return true;
        }
        list.settle(jobs);
    }
    fillStorage(buffer, capacity, list.instances.data(), bytes, jobs);
    return false;
}

}  // namespace fx
