#include "StatelessRenderer.h"

#include <algorithm>
#include <cstddef>
#include <unordered_map>

#include "render/PrivateGl.h"

#include "FogUniforms.h"
#include "GlStateGuard.h"
#include "ShaderLoader.h"
#include "../sim/ReactionRuntime.h"

namespace fx {

namespace {
constexpr GLuint kCornerAttrib = 0;
constexpr int kMaxStops = 16;
}  // namespace

/// One stateless reaction to draw in a pass: its ring, clock and look, taken at declare time.
struct StatelessRenderer::Draw {
    const StatelessRing* ring = nullptr;
    const ReactionDesc* desc = nullptr;
    float time = 0.0f;
    glm::vec3 terminal{0.0f};
};

struct StatelessRenderer::Gpu {
    /// A ring's copy on the GPU and how much of it is current.
    struct RingBuffer {
        GLuint vao = 0, buffer = 0;
        uint64_t uploaded = 0;  ///< ring.written() at the last upload
        int capacity = 0;
        int lastFrameSeen = 0;
    };
    GLuint program = 0;  ///< the cache's
    bool failed = false;
    GLuint corners = 0;
    std::unordered_map<const StatelessRing*, RingBuffer> rings;
    int frame = 0;
    struct {
        GLint view, proj, time, terminal, gravity, drag, fadeIn, fadeOut, rampCount, rampT, rampC,
            alphaCount, alphaT, alphaV, sizeCount, sizeT, sizeV, slice;
        FogUniforms fog;
    } u{};

    ~Gpu() {
        for (auto& kv : rings) {
            glDeleteBuffers(1, &kv.second.buffer);
            glDeleteVertexArrays(1, &kv.second.vao);
        }
        if (corners) glDeleteBuffers(1, &corners);
    }
};

StatelessRenderer::StatelessRenderer(HostAdapter* host, ProgramCache& programs)
    : host_(host), programs_(programs) {}

StatelessRenderer::~StatelessRenderer() {
    if (!gpu_) return;
    GlStateGuard guard;
    gpu_.reset();
}

int StatelessRenderer::declarePasses(const ViewInfo& view, FrameBuilder& frame,
                                     const std::vector<ReactionRuntime>& runtimes) {
    auto draws = std::make_shared<std::vector<Draw>>();
    int slots = 0;
    for (const ReactionRuntime& r : runtimes) {
        if (!r.stateless()) continue;
        const StatelessRing& ring = r.ring();
        const float now = static_cast<float>(r.time());
        if (ring.written() == 0 || !(ring.liveUntil() > now)) continue;
        draws->push_back(Draw{&ring, &r.desc(), now, r.terminal()});
        slots += static_cast<int>(std::min<uint64_t>(ring.written(), uint64_t(ring.capacity())));
    }
    if (draws->empty()) return 0;
    {
        // Built by prepare() (prepareGl); for a host that skipped it, here, before any pass.
        GlStateGuard guard;
        if (!ensureProgram()) return 0;
    }
    ViewInfo v = view;
    v.name = "";  // the host's string is not ours to keep
    const Target color = frame.sceneColor();
    frame.addPass(kPass, {}, {color}, [this, v, draws, color](PassContext& ctx) {
        GlStateGuard guard(v.depth);  // z-tested against the host's z-buffer
        ctx.bindForDraw(color);
        draw(v, *draws, HostClip::current());
    });
    return slots;
}

bool StatelessRenderer::ensureProgram() {
    if (!gpu_) gpu_ = std::make_unique<Gpu>();
    Gpu& g = *gpu_;
    if (g.program) return true;
    if (g.failed) return false;
    const ProgramCache::Key key = ProgramCache::Key::of(ProgramCache::Stateless);
    std::vector<std::string> errors;
    if (!programs_.tried(key)) programs_.build({key}, &errors);
    const uint32_t program = programs_.passProgram(ProgramCache::Stateless);
    if (!program) {
        g.failed = true;  // reported once; the other techniques keep drawing
        error_ = errors.empty() ? "fs_stateless_particles.glsl:0: did not build" : errors.front();
        host_->log(LogLevel::Error, ("fx: error[ShaderBuild] stateless particles:\n" + error_).c_str());
        return false;
    }
    adopt(program);
    return true;
}

void StatelessRenderer::adopt(uint32_t program) {
    Gpu& g = *gpu_;
    g.program = program;
    g.failed = false;
    error_.clear();
    auto loc = [&](const char* name) { return glGetUniformLocation(g.program, name); };
    g.u = {loc("uView"), loc("uProj"), loc("uTime"), loc("uTerminal"), loc("uGravity"), loc("uDrag"),
           loc("uFadeIn"), loc("uFadeOut"), loc("uRampCount"), loc("uRampT"), loc("uRampC"),
           loc("uAlphaCount"), loc("uAlphaT"), loc("uAlphaV"), loc("uSizeCount"), loc("uSizeT"),
           loc("uSizeV"), loc("uSlice"), FogUniforms::of(g.program)};
    if (g.corners) return;
    static const float kCorners[8] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};
    glGenBuffers(1, &g.corners);
    glBindBuffer(GL_ARRAY_BUFFER, g.corners);
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
}

bool StatelessRenderer::prepare(Diagnostics* out) {
    GlStateGuard guard;
    const bool ok = ensureProgram();
    if (!ok && out) addShaderDiagnostics(error_, out);
    return ok;
}

void StatelessRenderer::programsSwapped() {
    // Not in use: the reload only checked the files. In use: every key the cache tried was
    // built, so the stateless program is there.
    if (gpu_ && programs_.passProgram(ProgramCache::Stateless)) adopt(programs_.passProgram(ProgramCache::Stateless));
}

void StatelessRenderer::draw(const ViewInfo& view, const std::vector<Draw>& draws, const HostClip& clip) {
    if (!gpu_ || !gpu_->program) return;  // declarePasses built it (a reload may have swapped it)
    Gpu& g = *gpu_;
    ++g.frame;
    glUseProgram(g.program);
    glUniformMatrix4fv(g.u.view, 1, GL_FALSE, &view.view[0][0]);
    glUniformMatrix4fv(g.u.proj, 1, GL_FALSE, &view.proj[0][0]);
    glUniform2f(g.u.slice, view.slice.minDistance, view.slice.maxDistance);
    setFogUniforms(g.u.fog, view.fog);
    plainDrawState();
    clip.apply();  // a host's scissor on sceneColor keeps clipping the sparks
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    depthTestFor(view.depth);  // the hard technique's test, no depth writes

    for (const Draw& d : draws) {
        const StatelessRing& ring = *d.ring;
        Gpu::RingBuffer& rb = g.rings[d.ring];
        rb.lastFrameSeen = g.frame;
        const GLsizeiptr recordBytes = sizeof(StatelessRecord);
        if (!rb.vao || rb.capacity != ring.capacity()) {
            if (!rb.vao) {
                glGenVertexArrays(1, &rb.vao);
                glGenBuffers(1, &rb.buffer);
            }
            rb.capacity = ring.capacity();
            rb.uploaded = 0;
            glBindVertexArray(rb.vao);
            glBindBuffer(GL_ARRAY_BUFFER, g.corners);
            glEnableVertexAttribArray(kCornerAttrib);
            glVertexAttribPointer(kCornerAttrib, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
            glBindBuffer(GL_ARRAY_BUFFER, rb.buffer);
            glBufferData(GL_ARRAY_BUFFER, recordBytes * rb.capacity, nullptr, GL_DYNAMIC_DRAW);
            for (GLuint a = 0; a < 4; ++a) {
                glEnableVertexAttribArray(1 + a);
                glVertexAttribPointer(1 + a, 4, GL_FLOAT, GL_FALSE, GLsizei(recordBytes),
                                      reinterpret_cast<const void*>(size_t(a) * 4 * sizeof(float)));
                glVertexAttribDivisor(1 + a, 1);
            }
        }
        glBindVertexArray(rb.vao);
        glBindBuffer(GL_ARRAY_BUFFER, rb.buffer);
        // Only the slots written since the last upload (all of them after a full lap).
        const uint64_t cap = uint64_t(rb.capacity);
        const uint64_t fresh = ring.written() - rb.uploaded;
        if (fresh >= cap) {
            glBufferSubData(GL_ARRAY_BUFFER, 0, recordBytes * GLsizeiptr(cap), ring.data());
        } else if (fresh > 0) {
            const uint64_t first = rb.uploaded % cap;
            const uint64_t tail = std::min(fresh, cap - first);
            glBufferSubData(GL_ARRAY_BUFFER, recordBytes * GLintptr(first), recordBytes * GLsizeiptr(tail),
                            ring.data() + first);
            if (fresh > tail) {
                glBufferSubData(GL_ARRAY_BUFFER, 0, recordBytes * GLsizeiptr(fresh - tail), ring.data());
            }
        }
        rb.uploaded = ring.written();

        const ParticleDesc& p = d.desc->particle;
        glUniform1f(g.u.time, d.time);
        glUniform3f(g.u.terminal, d.terminal.x, d.terminal.y, d.terminal.z);
        glUniform3f(g.u.gravity, 0.0f, -p.gravity, 0.0f);
        glUniform1f(g.u.drag, p.drag);
        glUniform1f(g.u.fadeIn, p.fadeIn);
        glUniform1f(g.u.fadeOut, p.fadeOut);
        float t[kMaxStops] = {};
        float c[4 * kMaxStops] = {};
        const int stops = std::min<int>(kMaxStops, int(p.colorRamp.size()));
        for (int i = 0; i < stops; ++i) {
            t[i] = p.colorRamp[size_t(i)].t;
            for (int k = 0; k < 4; ++k) c[4 * i + k] = p.colorRamp[size_t(i)].rgba[k];
        }
        glUniform1i(g.u.rampCount, std::max(stops, 1));
        glUniform1fv(g.u.rampT, kMaxStops, t);
        glUniform4fv(g.u.rampC, kMaxStops, c);
        auto curve = [&](const std::vector<CurvePoint>& pts, GLint count, GLint ts, GLint vs) {
            float ct[kMaxStops] = {}, cv[kMaxStops] = {};
            const int n = std::min<int>(kMaxStops, int(pts.size()));
            for (int i = 0; i < n; ++i) ct[i] = pts[size_t(i)].t, cv[i] = pts[size_t(i)].v;
            glUniform1i(count, n);
            glUniform1fv(ts, kMaxStops, ct);
            glUniform1fv(vs, kMaxStops, cv);
        };
        curve(p.alphaOverLife, g.u.alphaCount, g.u.alphaT, g.u.alphaV);
        curve(p.sizeOverLife, g.u.sizeCount, g.u.sizeT, g.u.sizeV);
        const GLsizei instances = GLsizei(std::min<uint64_t>(ring.written(), cap));
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, instances);
    }
    // Rings of reactions gone after a reload: free their buffers.
    for (auto it = g.rings.begin(); it != g.rings.end();) {
        if (g.frame - it->second.lastFrameSeen > 120) {
            glDeleteBuffers(1, &it->second.buffer);
            glDeleteVertexArrays(1, &it->second.vao);
            it = g.rings.erase(it);
        } else {
            ++it;
        }
    }
}

}  // namespace fx
