#include "CApiBridge.h"

#include <cstddef>
#include <memory>

#include "../render/ShaderLoader.h"
#include "WorldBasis.h"

namespace fx {
namespace {

glm::vec3 vec3From(void (*get)(void*, float*), void* user) {
    float v[3] = {0.0f, 0.0f, 0.0f};
    if (get) get(user, v);
    return glm::vec3(v[0], v[1], v[2]);
}

// The most reads and writes a plugin pass declares (the host side spells these counts out).
constexpr size_t kMaxReads = 8;
constexpr size_t kMaxWrites = 4;

using PassFn = std::function<void(PassContext&)>;

void runPass(void* user, const fxPassContext* ctx) {
    CPassContext pass(*ctx);
    FrameScope running(FrameScope::Pass);
    (*static_cast<PassFn*>(user))(pass);
}
void releasePass(void* user) { delete static_cast<PassFn*>(user); }

}  // namespace

WheelContact CHostAdapter::wheel(int index) const {
    WheelContact w;
    if (!c_.wheel) return w;
    fxWheelContact c{};
    c_.wheel(c_.user, index, &c);
    w.position = toPluginWorld(up_, glm::vec3(c.position[0], c.position[1], c.position[2]));
    w.velocity = toPluginWorld(up_, glm::vec3(c.velocity[0], c.velocity[1], c.velocity[2]));
    w.slip = c.slip;
    // A surface outside the enum reads as asphalt (the emitter's default) rather than indexing
    // past the per-surface tables.
    w.surface = c.surface >= 0 && c.surface < static_cast<int>(Surface::Count) ? static_cast<Surface>(c.surface)
                                                                              : Surface::Asphalt;
    w.grounded = c.grounded != 0;
    w.rear = c.rear != 0;
    return w;
}

glm::vec3 CHostAdapter::wind() const { return toPluginWorld(up_, vec3From(c_.wind, c_.user)); }
glm::vec3 CHostAdapter::collisionPoint() const { return toPluginWorld(up_, vec3From(c_.collisionPoint, c_.user)); }

TextureRef CPassContext::texture(Target target, int attachment) {
    fxTextureRef c{};
    c_.texture(c_.user, target.id, attachment, &c);
    TextureRef r;
    r.name = c.name;
    r.format = static_cast<TargetFormat>(c.format);
    r.width = c.width;
    r.height = c.height;
    return r;
}

Target CFrameBuilder::createTarget(const char* name, const TargetDesc& desc) {
    fxTargetDesc c{};
    c.size = sizeof c;
    c.scale = desc.scale;
    c.width = desc.width;
    c.height = desc.height;
    c.format = static_cast<int>(desc.format);
    c.nearestFilter = desc.linearFilter ? 0 : 1;
    c.depth = desc.depth ? 1 : 0;
    return Target{c_.createTarget(c_.user, name, &c)};
}

void CFrameBuilder::addPass(const char* name, std::initializer_list<Target> reads,
                            std::initializer_list<Target> writes, PassFn execute) {
    if (reads.size() > kMaxReads || writes.size() > kMaxWrites) {
        errors_.refuse(ErrorCode::InvalidValue, "addPass", std::string(name) + " declares more reads or writes "
                                                           "than the C boundary carries (8, 4)");
        return;
    }
    uint32_t r[kMaxReads] = {}, w[kMaxWrites] = {};
    size_t i = 0;
    for (Target t : reads) r[i++] = t.id;
    i = 0;
    for (Target t : writes) w[i++] = t.id;
    auto fn = std::make_unique<PassFn>(std::move(execute));
    fxPassCallback cb{fn.get(), &runPass, &releasePass};
    fn.release();  // the host owns it now: release() deletes it
    c_.addPass(c_.user, name, r, int(reads.size()), w, int(writes.size()), cb);
}

namespace {
// API 2.0's fxFrameBuilder ended with addPass; 2.1 appended the z-buffer.
constexpr size_t kFrameBuilderSize20 = offsetof(fxFrameBuilder, sceneZBuffer);
bool hasZBufferFields(const fxFrameBuilder& f) { return f.size >= sizeof(fxFrameBuilder); }
// API 2.0's fxViewDesc ended with the depth range; 2.1 appended the view's place, the host
// scissor, fog and the distance slice.
constexpr size_t kViewDescSize20 = offsetof(fxViewDesc, viewportX);
static_assert(kViewDescSize20 % alignof(fxViewDesc) == 0,
              "a 2.0 host's sizeof(fxViewDesc) (with its tail padding) must equal the offset of viewportX");
bool hasFogFields(const fxViewDesc& v) { return v.size >= offsetof(fxViewDesc, sliceMaxDistance) + sizeof(float); }
}  // namespace

Target CFrameBuilder::sceneZBuffer() {
    return Target{hasZBufferFields(c_) && c_.sceneZBuffer ? c_.sceneZBuffer(c_.user) : 0u};
}

HostDepth CFrameBuilder::sceneZBufferMapping() {
    HostDepth d;
    if (!hasZBufferFields(c_)) return d;
    d.clipDepthZeroToOne = c_.zBufferClipZeroToOne != 0;
    if (c_.zBufferRangeNear != 0.0f || c_.zBufferRangeFar != 0.0f) {
        d.depthRangeNear = c_.zBufferRangeNear;
        d.depthRangeFar = c_.zBufferRangeFar;
    }
    return d;
}

std::string frameBuilderProblem(const fxFrameBuilder* f) {
    if (!f) return "frame is null; expected an fxFrameBuilder";
    if (f->size != sizeof(fxFrameBuilder) && f->size != kFrameBuilderSize20) {
        return "fxFrameBuilder::size = " + std::to_string(f->size) + "; expected " +
               std::to_string(sizeof(fxFrameBuilder)) + " (API 2.1) or " + std::to_string(kFrameBuilderSize20) +
               " (API 2.0)";
    }
    if (!f->sceneColor || !f->sceneDepth || !f->createTarget || !f->addPass) {
        return "fxFrameBuilder: sceneColor, sceneDepth, createTarget and addPass must all be set";
    }
    return std::string();
}

ViewInfo rightHandedView(const fxViewDesc& v, UpAxis up) {
    ViewInfo out;
    out.name = v.name ? v.name : "";
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            out.view[c][r] = v.view[c * 4 + r];
            out.proj[c][r] = v.proj[c * 4 + r];
        }
    }
    if (v.handedness == FX_LEFT_HANDED) {
        // F view negates the view matrix's third row; proj F negates the projection's third column.
        for (int c = 0; c < 4; ++c) out.view[c][2] = -out.view[c][2];
        out.proj[2] = -out.proj[2];
    }
    // The plugin's world is Y-up: view' = view B (after F, which acts on view space, not world).
    out.view = viewFromPluginWorld(up, out.view);
    out.eye = toPluginWorld(up, glm::vec3(v.eye[0], v.eye[1], v.eye[2]));
    out.nearPlane = v.nearPlane;
    out.farPlane = v.farPlane;
    out.width = v.width;
    out.height = v.height;
    if (hasFogFields(v)) {
        // GL's defaults for what the mode leaves unread; a mode outside FX_FOG_* keeps its value
        // so the view check refuses it (InvalidView).
        out.fog.mode = v.fogMode >= 0 && v.fogMode <= 255 ? static_cast<Fog::Mode>(v.fogMode) : static_cast<Fog::Mode>(255);
        out.fog.color = glm::vec3(v.fogColor[0], v.fogColor[1], v.fogColor[2]);
        if (v.fogMode == FX_FOG_LINEAR) {
            out.fog.start = v.fogStart;
            out.fog.end = v.fogEnd;
        } else {
            out.fog.density = v.fogDensity;
        }
        out.slice.minDistance = v.sliceMinDistance;
        out.slice.maxDistance = v.sliceMaxDistance;
    }
    out.depth = v.depthOrder == FX_DEPTH_REVERSED_Z ? DepthConvention::ReversedZ : DepthConvention::Standard;
    out.handedness = Handedness::RightHanded;
    out.x = v.viewportX;
    out.y = v.viewportY;
    out.targetWidth = v.targetWidth;
    out.targetHeight = v.targetHeight;
    out.clipToHostScissor = v.clipToScissor != 0;
    return out;
}

}  // namespace fx
