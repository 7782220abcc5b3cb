#include "TiledPath.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "render/PrivateGl.h"

#include "ComputeBindings.h"
#include "GlStateGuard.h"
#include "ImmediateFrame.h"
#include "PassDeclaration.h"
#include "SceneDepthSource.h"

namespace fx {
namespace {

constexpr int kEntryBinding = 1, kTileBinding = 2, kInstanceBinding = 0, kRecordBinding = 3, kLightBinding = 4,
              kShapeBinding = 5, kAccumImage = 0;
constexpr size_t kRecordBytes = 6 * 16;  // cs_particles_tiled.glsl's six vec4 per particle
constexpr size_t kLightBytes = 9 * 16;   // and its kLightStride, lit programs only
// The composite reads the accumulation on the opacity map's unit: the lit setup is done with it.
constexpr int kAtlasUnit = ParticleDraw::kAtlasUnit, kRampUnit = ParticleDraw::kRampUnit,
              kDepthUnit = ParticleDraw::kSceneDepthUnit, kOpacityUnit = ParticleDraw::kOpacityUnit, kAccumUnit = 3,
              kLitAtlasUnit = 4;
static_assert(kLitAtlasUnit < GlStateGuard::kTextureUnits, "a unit the guard puts back");
static_assert(kShapeBinding < ComputeBindingsScope::kBindings, "a binding ComputeBindingsScope puts back");
static_assert(kAccumImage == ComputeBindingsScope::kImage, "the image unit ComputeBindingsScope puts back");

std::atomic<uint64_t> gCpuListViews{0}, gGpuSortedViews{0}, gDeferredBinViews{0}, gDeferredFallbacks{0},
    gGpuBinnedViews{0}, gGatheredViews{0};

// render.near_fade as the shaders' line in depth (ParticleDraw's nearFadeMap).
glm::vec2 nearFadeMap(float fade, float nearPlane) {
    return fade > 0.0f ? glm::vec2(1.0f / fade, -nearPlane / fade) : glm::vec2(0.0f, 1.0f);
}

// The pixels of the tiles that hold particles: the only ones the pass reads the scene depth at
// (the immediate path copies no more of the host's z-buffer). From the bins, so the particles are
// not bounded a second time.
ScreenRect tilesBound(const TileBins& bins, int width, int height) {
    constexpr int kTile = ScreenTiles::kTileSize;
    ScreenRect r;
    r.whole = false;
    if (bins.tileCount() == 0) return r;
    r.x0 = width;
    r.x1 = 0;
    r.y0 = int(bins.tiles[1]) * kTile;                                            // row-major: the first
    r.y1 = std::min(height, (int(bins.tiles[bins.tiles.size() - 3]) + 1) * kTile);  // and the last row
    for (size_t t = 0; t < bins.tiles.size(); t += 4) {
        r.x0 = std::min(r.x0, int(bins.tiles[t]) * kTile);
        r.x1 = std::max(r.x1, std::min(width, (int(bins.tiles[t]) + 1) * kTile));
    }
    return r;
}

}  // namespace

TiledPath::TiledPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch)
    : draw_(draw), sizeMismatch_(std::move(sizeMismatch)) {}

TiledPath::~TiledPath() {
    // The renderer deletes its GL objects inside a guard with the context current (~ParticleRenderer).
    if (!privateGlContextCurrent()) return;
    const uint32_t buffers[7] = {tileBuffer_,  recordBuffer_, coverVbo_,   instanceBuffer_,
                                 entryBuffer_, lightBuffer_,  shapeBuffer_};
    for (uint32_t b : buffers) {
        if (b) glDeleteBuffers(1, &b);
    }
    if (accum_) glDeleteTextures(1, &accum_);
    if (coverVao_) glDeleteVertexArrays(1, &coverVao_);
}

uint64_t TiledPath::cpuListViews() { return gCpuListViews.load(std::memory_order_relaxed); }
uint64_t TiledPath::gpuSortedViews() { return gGpuSortedViews.load(std::memory_order_relaxed); }
uint64_t TiledPath::deferredBinViews() { return gDeferredBinViews.load(std::memory_order_relaxed); }
uint64_t TiledPath::deferredFallbacks() { return gDeferredFallbacks.load(std::memory_order_relaxed); }
uint64_t TiledPath::gpuBinnedViews() { return gGpuBinnedViews.load(std::memory_order_relaxed); }
uint64_t TiledPath::gatheredViews() { return gGatheredViews.load(std::memory_order_relaxed); }

bool TiledPath::declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& record, const Jobs& jobs,
                        Fallback fallback) {
    const ViewInfo& view = record->view;
    // Hard particles are cut against the scene depth too: the pass reads it whatever the batches
    // (a host that hands none in gets the full-resolution pass).
    const SceneDepthSource source = sceneDepthSource(frame, view);
    const Target depth = source.target;
    const SceneDepthDecode decode = source.decode;
    if (!depth.valid()) return false;
    bool lit = false;
    for (const DrawBatch& batch : record->list.batches) lit = lit || litBatch(*record, batch);
    if (lit && !litOk()) return false;
    // An unsorted list's lists can only come from the GPU, which sorts its particles first.
    if (record->list.orderPending && !sort_.orderOk()) return false;
    // The bins of a view the GPU orders wait for the pass (see deferBins()). The immediate path
    // (renderView) bins here where the host's threads bin it, so that its copy of the scene depth
    // is narrowed to them; where the GPU bins it (gpuBins()) it waits too, and the copy is the
    // view's (the bins are known only once the passes run).
    const bool immediate = dynamic_cast<ImmediateFrame*>(&frame) != nullptr;
    const bool deferred =
        record->list.orderPending && fallback && deferBins() && (!immediate || binsOnGpu());
    // A list whose gather is pending (ParticleRenderer: where the GPU bins) waits for the first
    // pass only where that pass takes it (run(), fillInstances) and nothing before it reads it.
    if (!(deferred && binsOnGpu())) record->list.settle(jobs);
    if (!deferred) {
        TileBins::Range ranges[kMaxBatches];
        const int batchCount = batchRanges(*record, ranges);
        const BillboardReach reach = draw_.billboardReach(*record, false);
        if (!binParticles(view, record->list.instances.data(), ranges, batchCount, &reach, &record->bins, jobs,
                          record->list.orderPending ? TileBins::Fill::Ranges : TileBins::Fill::Pairs) ||
            !sort_.fits(record->bins)) {
            return false;
        }
        if (!record->list.orderPending && record->bins.entryCount <= cpuListLimit(software_)) {
            writeEntries(&record->bins, jobs);
        }
        narrowDepthRead(frame, tilesBound(record->bins, view.width, view.height), view.width, view.height);
    }
    const Target color = frame.sceneColor();
    const Target opacity = lit ? record->opacity : Target{};  // lit smoke's opacity map, where there is one
    record->tiledSetUp = false;
    if (deferred) {
        // The first of its two passes (see deferBins()). It writes sceneColor as the second does
        // (it draws nothing into it): a frame graph keeps the two in order and culls them together.
        addPassReading(frame, kSetupPass, {depth, opacity}, color,
                       [this, record, depth, decode, color, opacity](PassContext& ctx) {
                           if (!targetsFitView(ctx, record->view, color, depth, nullptr)) return;  // told below
                           GlStateGuard guard;
                           DebugGroup group(kSetupPass);
                           run(ctx, *record, color, depth, decode, opacity, Stage::Setup);
                       });
    }
    addPassReading(frame, kPass, {depth, opacity}, color,
                   [this, record, depth, decode, color, opacity, deferred, fallback](PassContext& ctx) {
                       if (!targetsFitView(ctx, record->view, color, depth, sizeMismatch_)) return;
                       bool drawn = true;
                       {
                           GlStateGuard guard;  // nothing z-tested: the compute shader compares depths itself
                           DebugGroup group(kPass);
                           drawn = run(ctx, *record, color, depth, decode, opacity, deferred ? Stage::Tiles : Stage::Whole);
                       }
                       if (!drawn) {
                           // Bins the pass could not take after all: the raster path, as declare()
                           // would have sent the view to had it binned it.
                           gDeferredFallbacks.fetch_add(1, std::memory_order_relaxed);
                           fallback(ctx, color, depth, decode, opacity);
                       }
                       record->drawn = true;
                   });
    return true;
}

int TiledPath::batchRanges(const ParticleView& v, TileBins::Range* ranges) {
    const int batchCount = int(v.list.batches.size());
    for (int b = 0; b < batchCount; ++b) {
        const DrawBatch& batch = v.list.batches[size_t(b)];
        ranges[b] = {batch.first, batch.count, batch.technique == Technique::Spherical};
    }
    return batchCount;
}

void TiledPath::ensureObjects(int width, int height) {
    if (!recordBuffer_) glGenBuffers(1, &recordBuffer_);
    if (!coverVao_) {
        glGenVertexArrays(1, &coverVao_);
        glGenBuffers(1, &coverVbo_);
        glBindVertexArray(coverVao_);
        glBindBuffer(GL_ARRAY_BUFFER, coverVbo_);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    }
    if (!accum_ || width > accumWidth_ || height > accumHeight_) {
        // Grows only: split-screen views of different sizes share it.
        accumWidth_ = std::max(width, accumWidth_);
        accumHeight_ = std::max(height, accumHeight_);
        if (accum_) glDeleteTextures(1, &accum_);
        glGenTextures(1, &accum_);
        glActiveTexture(GLenum(GL_TEXTURE0 + kAccumUnit));
        glBindTexture(GL_TEXTURE_2D, accum_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, accumWidth_, accumHeight_, 0, GL_RGBA, GL_HALF_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        glBindTexture(GL_TEXTURE_2D, 0);
        glActiveTexture(GL_TEXTURE0);
    }
}

bool TiledPath::run(PassContext& ctx, ParticleView& v, Target color, Target depth, const SceneDepthDecode& decode,
                    Target opacity, Stage stage) {
    TileBins& bins = v.bins;
    const ViewInfo& view = v.view;
    const bool deferred = stage != Stage::Whole;
    // The second pass of a view binned in its pass does the first's work itself where that did
    // not run for this view, last (it failed, or a host graph ran another view's passes between
    // the two: the views share the sort's and the records' buffers).
    const bool setUp = stage == Stage::Tiles && v.tiledSetUp && setUpView_ == &v;
    v.tiledSetUp = false;
    setUpView_ = nullptr;
    if (!setUp) gpuBinned_ = false;
    if ((!deferred && bins.tileCount() == 0) || !ok() || v.list.particleCount() == 0) return true;
    bool lit = false;
    for (const DrawBatch& batch : v.list.batches) lit = lit || litBatch(v, batch);
    if (lit && !litOk()) return true;  // declare() said so; a reload since may have lost them
    ComputeBindingsScope bindings;
    ensureObjects(view.width, view.height);

    // The instances (and below, the bins' lists and tiles) go to storage buffers of the pass's
    // own, kept (not orphaned) and written through a mapping on the host's threads (the
    // instances gathered from the pools there where the list left that to the pass). Through the
    // raster path's vertex buffer, orphaned each frame and read here by compute, the H200's driver
    // gave the CPU a store it writes slowly: 2.25 ms for the 8 MB of 256,000 particles, where the
    // sort's 4 MB take 0.25 ms.
    const int count = v.list.particleCount();
    if (!setUp) {
        if (deferred) glFlush();  // the scene's passes to the GPU while the CPU writes (and bins, in the next pass)
        if (fillInstances(&instanceBuffer_, &instanceCapacity_, v.list, draw_.jobs())) {
            gGatheredViews.fetch_add(1, std::memory_order_relaxed);
        }
    }
    TileSort::DepthOrder order;
    if (v.list.orderPending) {
        order.instances = instanceBuffer_;
        order.eye = view.eye;
        order.forward = viewForward(view);
        order.batchCount = int(v.list.batches.size());
        for (int b = 0; b < order.batchCount; ++b) {
            if (v.list.batches[size_t(b)].backToFront) order.backToFront |= 1u << b;
        }
    }
    // Deferred bins: the particles' order, which needs none, goes to the GPU first.
    TileBins::Range ranges[kMaxBatches];
    const int batchCount = batchRanges(v, ranges);
    if (deferred && !setUp) {
        if (placeBatches(ranges, batchCount, &bins) < 0) return false;
        stageTimes_.begin(uint32_t(count));
        sort_.sortParticles(uint32_t(count), order, bins);
        stageTimes_.mark(TiledStageTimes::Ordered);
    }

    // What the pass reads.
    ColorRampTexture& ramp = draw_.ramp();
    ramp.upload();
    const SmokeAtlas& atlas = draw_.atlas();
    bindTextureUnit(kAtlasUnit, atlas.texture(), draw_.atlasSampler().name());
    bindTextureUnit(kRampUnit, ramp.texture());
    const TextureRef depthRef = depth.valid() ? ctx.texture(depth, 0) : TextureRef{};
    draw_.depthSampler().bindTexture(kDepthUnit, depthRef.name);
    const SceneDepthDecode placed = decode.placedFor(depthRef, view, true);  // addressed as in sceneColor
    if (depthRef.name) sceneDepthBarrier(decode);

    // 1. Each particle's record, once (the vertex shader's work).
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceBinding, instanceBuffer_);
    const size_t recordBytes = size_t(count) * kRecordBytes;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, recordBuffer_);
    if (recordBytes > recordCapacity_) {
        recordCapacity_ = std::max(recordBytes, 2 * recordCapacity_);
        glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(recordCapacity_), nullptr, GL_DYNAMIC_COPY);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRecordBinding, recordBuffer_);
    if (lit) {
        TileSort::ensureBuffer(&lightBuffer_, &lightCapacity_, size_t(count) * kLightBytes);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightBinding, lightBuffer_);
        bindTextureUnit(kOpacityUnit, opacity.valid() ? ctx.texture(opacity, 0).name : 0);
        bindTextureUnit(kLitAtlasUnit, atlas.litTexture(), draw_.atlasSampler().name());
        // The trimmed polygons the raster path would draw the billboards with (their light is
        // interpolated between the polygon's vertices), uploaded when the atlas's change.
        const std::vector<glm::vec4>& shapes = draw_.shapeTable();
        if (!shapeBuffer_ || shapes != shapesUploaded_) {
            if (!shapeBuffer_) glGenBuffers(1, &shapeBuffer_);
            glBindBuffer(GL_SHADER_STORAGE_BUFFER, shapeBuffer_);
            const glm::vec4 none(0.0f);  // a store of one vec4 where there is no table (the quads read none)
            glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<size_t>(shapes.size(), 1) * sizeof(glm::vec4)),
                         shapes.empty() ? &none[0] : &shapes[0][0], GL_STATIC_DRAW);
            shapesUploaded_ = shapes;
        }
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShapeBinding, shapeBuffer_);
    }
    // The lit smoke's light: the scene's sun in view space, each batch's share (ParticleDraw's
    // setLightUniforms, per batch).
    const LightState& light = v.settings.light;
    const glm::vec3 sunView = lit ? glm::normalize(glm::mat3(view.view) * light.toSun) : glm::vec3(0.0f);
    const glm::mat4 viewToShadow = lit ? v.worldToShadow * glm::inverse(view.view) : glm::mat4(1.0f);
    auto setLight = [&](const ShadeUniforms& u) {
        if (!lit) return;
        glUniform3f(u.sunView, sunView.x, sunView.y, sunView.z);
        glUniform3f(u.sunColor, light.sunColor.x, light.sunColor.y, light.sunColor.z);
        glUniform1i(u.shadowed, opacity.valid() ? 1 : 0);
        glUniformMatrix4fv(u.viewToShadow, 1, GL_FALSE, &viewToShadow[0][0]);
        glUniform1i(u.opacity, kOpacityUnit);
        glUniform1i(u.litAtlas, kLitAtlasUnit);
        const bool trimmed = v.settings.shape == ParticleShape::Trimmed && !draw_.shapeTable().empty();
        glUniform1i(u.trimmed, trimmed ? 1 : 0);
        glUniform1i(u.shapeBuckets, draw_.atlas().shapes().buckets());
        glUniform1f(u.lodScale, draw_.lodScaleFor(view.proj, float(view.height)));
        glm::vec4 setupLight[kMaxBatches], shadeLight[kMaxBatches];
        const int batchCount = int(v.list.batches.size());
        for (int b = 0; b < batchCount; ++b) {
            const DrawBatch& batch = v.list.batches[size_t(b)];
            const LightingDesc& l = batch.lighting;
            const glm::vec3 ambient = light.ambient * l.ambient;
            setupLight[b] = glm::vec4(l.anisotropy, l.absorption, l.normalStrength, litBatch(v, batch) ? 1.0f : 0.0f);
            shadeLight[b] = glm::vec4(ambient, l.scattering);
        }
        glUniform4fv(u.batchLight, batchCount, &setupLight[0][0]);
        glUniform4fv(u.batchShade, batchCount, &shadeLight[0][0]);
    };
    const glm::vec4 pixelToNdc(2.0f / float(view.width), 2.0f / float(view.height), -1.0f, -1.0f);
    if (!setUp) {
        glUseProgram(lit ? setupLit_ : setup_);
        const ShadeUniforms& u = lit ? setupLitUniforms_ : setupUniforms_;
        setLight(u);
        glUniformMatrix4fv(u.view, 1, GL_FALSE, &view.view[0][0]);
        glUniformMatrix4fv(u.proj, 1, GL_FALSE, &view.proj[0][0]);
        glUniform1f(u.nearPlane, view.nearPlane);
        glUniform1f(u.farPlane, view.farPlane);
        glUniform1i(u.ramp, kRampUnit);
        setSceneDepthDecode(u.decode, placed);  // the soft fade's line folds the decode in
        setFogUniforms(u.fog, view.fog);
        glm::vec4 batchA[kMaxBatches], batchB[kMaxBatches];
        glm::ivec2 range[kMaxBatches];
        const int batchCount = int(v.list.batches.size());
        for (int b = 0; b < batchCount; ++b) {
            const DrawBatch& batch = v.list.batches[size_t(b)];
            const float kind = batch.technique == Technique::Hard ? 0.0f
                               : batch.technique == Technique::Soft ? 1.0f
                                                                    : 2.0f;
            batchA[b] = glm::vec4(ramp.rowV(batch.rampRow), float(static_cast<int>(batch.blend)), batch.softScale,
                                  batch.contrastPower);
            batchB[b] = glm::vec4(nearFadeMap(batch.nearFade, view.nearPlane), kind, 0.0f);
            range[b] = glm::ivec2(batch.first, batch.count);
        }
        glUniform4fv(u.batchA, batchCount, &batchA[0][0]);
        glUniform4fv(u.batchB, batchCount, &batchB[0][0]);
        glUniform2iv(u.batchRange, batchCount, &range[0][0]);
        glUniform1i(u.batchCount, batchCount);
        glUniform1i(u.instanceCount, count);
        // One pixel in ray slope, the larger of x and y (ParticleDraw's pixelSlopeOf, per axis).
        const float slopeX = 2.0f / std::fmax(std::fabs(view.proj[0][0]) * float(view.width), 1e-6f);
        const float slopeY = 2.0f / std::fmax(std::fabs(view.proj[1][1]) * float(view.height), 1e-6f);
        glUniform1f(u.pixelSlope, std::fmax(slopeX, slopeY));
        glUniform4f(u.pixelToNdc, pixelToNdc.x, pixelToNdc.y, pixelToNdc.z, pixelToNdc.w);
        glUniform1f(u.atlasTexels, float(atlas.width()));
        const int groups = (count + 63) / 64;
        const int groupsX = std::min(groups, 65535);  // the least GL_MAX_COMPUTE_WORK_GROUP_COUNT
        glUniform1i(u.groupsX, groupsX);
        glDispatchCompute(GLuint(groupsX), GLuint((groups + groupsX - 1) / groupsX), 1);
        if (deferred) stageTimes_.mark(TiledStageTimes::Recorded);
    }

    // The GPU's bins (gpuBins()), queued behind the order and the records: the next pass reads
    // back what they found.
    if (deferred && !setUp && binsOnGpu()) {
        uint32_t spheres = 0;
        for (int b = 0; b < batchCount; ++b) spheres |= ranges[b].sphere ? 1u << b : 0u;
        const BillboardReach reach = draw_.billboardReach(v, false);
        gpuBinned_ = sort_.binOnGpu(view, instanceBuffer_, uint32_t(count), spheres, reach, bins, &tileBuffer_,
                                    &tileCapacity_);
    }
    if (deferred && !setUp) stageTimes_.mark(TiledStageTimes::Binned);

    if (stage == Stage::Setup) {
        // The first pass's work to the GPU, which does it while the next pass waits for its bins
        // (or, without the GPU's, while the host's threads bin them there).
        glFlush();
        v.tiledSetUp = true;
        setUpView_ = &v;
        return true;
    }

    // Deferred bins, now that the GPU has the scene, the particles' order, their records and (where
    // it bins them) the bins to work on: flushed (by the first pass, or here), so that it does
    // while the host's threads bin, or until the read-back below.
    if (deferred) {
        if (!setUp) glFlush();
        bool binned = false;
        if (gpuBinned_) {
            // Read back from the GPU's bins (a wait for what it had queued before them).
            binned = sort_.readGpuBins(&bins);
            if (binned) gGpuBinnedViews.fetch_add(1, std::memory_order_relaxed);
        } else {
            v.list.settle(draw_.jobs());  // where the GPU's bins could not be issued after all
            const BillboardReach reach = draw_.billboardReach(v, false);
            binned = binParticles(view, v.list.instances.data(), ranges, batchCount, &reach, &bins, draw_.jobs(),
                                  TileBins::Fill::Ranges);
        }
        gpuBinned_ = false;
        if (!binned || !sort_.fits(bins)) {
            sort_.dropOrder();
            return false;
        }
        gDeferredBinViews.fetch_add(1, std::memory_order_relaxed);
        stageTimes_.mark(TiledStageTimes::TilesStart);
        if (bins.tileCount() == 0) {
            sort_.dropOrder();
            return true;  // nothing on screen
        }
    }

    // The bins' lists (written on the CPU when declared, else written and sorted on the GPU:
    // TileSort.h, which reads the instances where it sorts the particles too) and tiles.
    uint32_t entries = 0;
    if (!bins.entries.empty()) {
        fillStorage(&entryBuffer_, &entryCapacity_, bins.entries.data(), bins.entries.size() * sizeof(uint32_t), draw_.jobs());
        entries = entryBuffer_;
        gCpuListViews.fetch_add(1, std::memory_order_relaxed);
    } else {
        entries = sort_.run(bins, draw_.jobs(), v.list.orderPending ? &order : nullptr, [this, deferred] {
            if (deferred) stageTimes_.mark(TiledStageTimes::Emitted);
        });
        if (deferred) stageTimes_.mark(TiledStageTimes::Sorted);
        gGpuSortedViews.fetch_add(1, std::memory_order_relaxed);
    }
    if (!entries) return true;
    if (bins.gpuParticles == 0) {  // the GPU's bins listed their tiles there already
        fillStorage(&tileBuffer_, &tileCapacity_, bins.tiles.data(), bins.tiles.size() * sizeof(uint32_t), draw_.jobs());
    }
    // The sort bound its own buffers to these bindings.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceBinding, instanceBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEntryBinding, entries);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileBinding, tileBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRecordBinding, recordBuffer_);
    if (lit) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightBinding, lightBuffer_);
    glBindImageTexture(kAccumImage, accum_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    // The records for the tiles; and the image's stores after the last view's composite read it
    // (split screen: one image for every view).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // 2. The tiles: every pixel through its tile's particles.
    glUseProgram(lit ? shadeLit_ : shade_);
    {
        const ShadeUniforms& u = lit ? shadeLitUniforms_ : shadeUniforms_;
        setLight(u);
        glUniformMatrix4fv(u.proj, 1, GL_FALSE, &view.proj[0][0]);
        glUniform1f(u.nearPlane, view.nearPlane);
        glUniform1i(u.atlas, kAtlasUnit);
        glUniform1i(u.sceneDepth, kDepthUnit);
        setSceneDepthDecode(u.decode, placed);
        glUniform2i(u.viewSize, view.width, view.height);
        glUniform4f(u.pixelToNdc, pixelToNdc.x, pixelToNdc.y, pixelToNdc.z, pixelToNdc.w);
        const int tiles = bins.tileCount();
        const int groupsX = std::min(tiles, 65535);
        const int groupsY = (tiles + groupsX - 1) / groupsX;
        glUniform1i(u.tileCount, tiles);
        glUniform1i(u.groupsX, groupsX);
        glDispatchCompute(GLuint(groupsX), GLuint(groupsY), 1);
    }
    if (deferred) stageTimes_.mark(TiledStageTimes::Shaded);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

    // The covered tiles onto sceneColor.
    ctx.bindForDraw(color);
    const HostClip clip = HostClip::current();
    plainDrawState();
    clip.apply();
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(composite_);
    bindTextureUnit(kAccumUnit, accum_);
    glUniform1i(compositeAccum_, kAccumUnit);
    glUniform2i(compositeOrigin_, placed.drawOrigin.x, placed.drawOrigin.y);
    glUniform2f(compositeViewSize_, float(bins.cover.viewWidth), float(bins.cover.viewHeight));
    glBindVertexArray(coverVao_);
    glBindBuffer(GL_ARRAY_BUFFER, coverVbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bins.cover.vertices.size() * sizeof(float)), bins.cover.vertices.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(bins.cover.vertices.size() / 2));
    if (deferred) {
        stageTimes_.end();
        const std::string report = stageTimes_.takeReport();
        if (!report.empty() && stageLog_) stageLog_(report);
    }
    return true;
}

}  // namespace fx
