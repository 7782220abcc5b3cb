// A C++ host of the plugin's C++ layer (fx/Plugin.h and the fx/detail bridges it includes),
// written so that era_test.sh can compile it under C++11, 14 and 17 with -pedantic-errors on every
// compiler it finds. It only has to compile: each virtual of the host's side is implemented and
// each call of fx::Plugin the layer forwards through the C table is made, so every inline function
// and template of the layer is instantiated (a header that merely parses proves less: templates
// are checked only when used). Nothing here is C++14 or later.
#include <fx/Plugin.h>

#include <cstdio>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace {

class Host : public fx::HostAdapter {
public:
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return 1; }
    fx::WheelContact wheel(int) const override {
        fx::WheelContact w;
        w.slip = 1.0f;
        w.grounded = true;
        w.rear = true;
        return w;
    }
    glm::vec3 wind() const override { return glm::vec3(1.0f, 0.0f, 0.0f); }
    void log(fx::LogLevel, const char* message) override { std::printf("%s\n", message); }
};

class Context : public fx::PassContext {
public:
    void bindForDraw(fx::Target) override {}
    fx::TextureRef texture(fx::Target, int) override { return fx::TextureRef(); }
    int width(fx::Target) override { return 64; }
    int height(fx::Target) override { return 64; }
};

class Frame : public fx::FrameBuilder {
public:
    fx::Target sceneColor() override { return make(1); }
    fx::Target sceneDepth() override { return make(2); }
    fx::Target createTarget(const char*, const fx::TargetDesc&) override { return make(++next_); }
    void addPass(const char*, std::initializer_list<fx::Target> reads, std::initializer_list<fx::Target> writes,
                 std::function<void(fx::PassContext&)> execute) override {
        passes.push_back(execute);
        touched += static_cast<int>(reads.size() + writes.size());
    }
    std::vector<std::function<void(fx::PassContext&)> > passes;
    int touched = 0;

private:
    static fx::Target make(uint32_t id) {
        fx::Target t;
        t.id = id;
        return t;
    }
    uint32_t next_ = 10;
};

}  // namespace

int main() {
    Host host;
    fx::PluginImports imports;
    imports.host = &host;
    fx::ErrorCode error = fx::ErrorCode::None;
    std::unique_ptr<fx::Plugin> plugin = fxCreatePlugin(imports, &error);
    if (!plugin) return 1;

    fx::Diagnostics diagnostics;
    plugin->loadReactions("smoke.yaml", &diagnostics);
    plugin->loadReactionsFromText("inline.yaml", "reactions: []\n", &diagnostics);
    for (size_t i = 0; i < diagnostics.size(); ++i) std::printf("%s\n", diagnostics[i].str().c_str());
    plugin->pollHotReload(&diagnostics);
    fx::RenderOptions options = plugin->renderOptions();
    plugin->setRenderOptions(options);
    plugin->setParticleShape(plugin->particleShape());
    plugin->setQuarterResEdges(plugin->quarterResEdges());
    plugin->setFadeClassification(plugin->fadeClassification());
    plugin->setFadeClassCounting(true);
    fx::FadeClassCounts counts = plugin->fadeClassCounts();
    (void)counts;
    plugin->setSceneLight(fx::SceneLight());
    plugin->clearSceneLight();
    plugin->prepareGl(&diagnostics);
    plugin->pollShaderReload(&diagnostics);

    float collision = 0.0f;
    for (int i = 0; i < plugin->reactionCount(); ++i) {
        plugin->continueReaction(i, 1.0f / 60.0f, &collision);
        fx::ReactionStats s = plugin->reactionStats(i);
        std::printf("%s %s %s %d\n", plugin->reactionName(i).c_str(), plugin->reactionFile(i).c_str(),
                    s.technique.c_str(), plugin->reactionParticlesAlive(i));
        std::printf("%s\n", plugin->reactionValue(i, "emission.rate").c_str());
    }
    plugin->fireReaction("burst", glm::vec3(0.0f));
    std::vector<fx::ReactionKeyInfo> schema = plugin->reactionSchema();
    std::vector<std::string> files = plugin->reactionFiles();
    std::printf("%u keys, %u files\n", static_cast<unsigned>(schema.size()), static_cast<unsigned>(files.size()));

    fx::ViewInfo view;
    view.name = "main";
    view.width = 64;
    view.height = 64;
    Frame frame;
    plugin->declarePasses(view, frame);
    fx::SmokeShadow shadow = plugin->declareShadowPasses(view, frame);
    Context context;
    for (size_t i = 0; i < frame.passes.size(); ++i) frame.passes[i](context);
    fx::HostDepth depth;
    depth.source = fx::HostDepth::Source::None;
    plugin->renderView(view, depth);

    fx::Stats stats = plugin->stats();
    fx::ParticleCheck check = plugin->checkParticles();
    return shadow.valid() || stats.apiErrors != 0 || check.nonFinite != 0 ? 1 : 0;
}
