// irrlicht_host: a legacy engine drives the CubeFx plugin through its C table (fx/fx.h).
// Irrlicht 1.8 opens an OpenGL window and draws its own scene (scene.cpp) with smgr->drawAll();
// the plugin then adds the smoke with ONE call, fxApi.renderView, which reads the scene depth from
// the window's own z-buffer and restores every GL state it touches, so Irrlicht's cached state
// stays true and its GUI is drawn on top as usual. No second depth pass, no render target of the
// host's, no state reset.
//
//   irrlicht_host [--frames N] [--size WxH] [--screenshot out.png] [--reactions smoke.yaml]
//                 [--no-smoke] [--no-plugin]
//   --no-smoke   the plugin runs as usual, but the last frame (the screenshot) is drawn without
//                renderView: it must equal a --no-plugin frame pixel for pixel.
//   --no-plugin  the plugin is never created.
// Prints the label's rectangle and the median frame time (CPU clock, beginScene to endScene).
//
// The lines between the fx-adapter begin/end markers are everything the host adds for the
// plugin (examples/count_adapter_lines.sh counts them).
#include <irrlicht.h>
#include <GL/glx.h>  // glXGetProcAddress: the plugin loads GL through the host's context

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <fx/fx.h>

#include "scene.h"

using namespace irr;

namespace {

constexpr float kStep = 1.0f / 60.0f;  // fixed simulation step: a frame's image depends on its index only

struct Options {
    int frames = 120;
    u32 width = 640, height = 480;
    std::string screenshot, reactions = "smoke.yaml";
    bool smoke = true, plugin = true;
};

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--frames" && more) o.frames = std::atoi(argv[++i]);
        else if (a == "--size" && more && std::sscanf(argv[++i], "%ux%u", &o.width, &o.height) == 2) {}
        else if (a == "--screenshot" && more) o.screenshot = argv[++i];
        else if (a == "--reactions" && more) o.reactions = argv[++i];
        else if (a == "--no-smoke") o.smoke = false;
        else if (a == "--no-plugin") o.plugin = false;
        else return false;
    }
    return o.frames > 0 && o.width >= 64 && o.height >= 64;
}

// fx-adapter begin: callbacks (fxHostCallbacks)
void* fxProc(void*, const char* name) { return reinterpret_cast<void*>(glXGetProcAddress(reinterpret_cast<const GLubyte*>(name))); }
void fxLog(void*, int level, const char* message) { std::fprintf(stderr, "[fx %d] %s\n", level, message); }
int fxWheelCount(void*) { return 4; }
// Wheels 0-1 front, 2-3 rear; the rear ones slide (slip 1) as the car drifts, the front ones roll.
void fxWheel(void* user, int index, fxWheelContact* out) {
    const CarState& car = *static_cast<const CarState*>(user);
    const core::vector3df right = core::vector3df(0.0f, 1.0f, 0.0f).crossProduct(car.heading);  // left-handed
    const core::vector3df p = car.position + car.heading * (index < 2 ? 1.4f : -1.4f) + right * (index % 2 ? 0.8f : -0.8f);
    *out = {{p.X, 0.0f, p.Z}, {car.velocity.X, 0.0f, car.velocity.Z}, index < 2 ? 0.1f : 1.0f, FX_SURFACE_ASPHALT, 1, index >= 2};
}
// fx-adapter end

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr, "usage: irrlicht_host [--frames N] [--size WxH] [--screenshot out.png] "
                             "[--reactions smoke.yaml] [--no-smoke] [--no-plugin]\n");
        return 2;
    }
    SIrrlichtCreationParameters params;
    params.DriverType = video::EDT_OPENGL;
    params.WindowSize = core::dimension2du(o.width, o.height);
    params.Bits = 24;
    params.ZBufferBits = 24;
    params.Vsync = false;
    // Irrlicht 1.8's createScreenShot reads GL_FRONT, which Mesa's software GLX under Xvfb leaves
    // black after a swap: a window that takes a screenshot draws into its front buffer.
    params.Doublebuffer = o.screenshot.empty();
    IrrlichtDevice* device = createDeviceEx(params);
    if (!device) {
        std::fprintf(stderr, "irrlicht_host: Irrlicht could not open an OpenGL window (no X display?)\n");
        return 3;
    }
    device->setWindowCaption(L"irrlicht_host: CubeFx smoke in Irrlicht 1.8");
    video::IVideoDriver* driver = device->getVideoDriver();
    scene::ISceneManager* smgr = device->getSceneManager();
    gui::IGUIEnvironment* gui = device->getGUIEnvironment();
    Scene scene = buildScene(device);
    CarState car = carAt(0.0f);

    // fx-adapter begin: setup
    const fxApi* fx = o.plugin ? fxGetApi(FX_API_VERSION) : nullptr;
    fxHostCallbacks host = FX_DESC_INIT(fxHostCallbacks);
    host.user = &car;
    host.getProcAddress = fxProc;
    host.log = fxLog;
    host.wheelCount = fxWheelCount;
    host.wheel = fxWheel;
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    desc.host = &host;
    fxPlugin* plugin = fx ? fx->create(&desc, nullptr) : nullptr;
    if (o.plugin && (!plugin || !fx->loadReactions(plugin, o.reactions.c_str(), nullptr) || !fx->prepareGl(plugin, nullptr))) {
        std::fprintf(stderr, "irrlicht_host: the plugin could not start (see the [fx] lines)\n");
        return 1;
    }
    // fx-adapter end

    std::vector<double> frameMs;
    for (int frame = 0; frame < o.frames && device->run(); ++frame) {
        const auto start = std::chrono::steady_clock::now();
        car = carAt(float(frame) * kStep);
        placeCar(scene, car);
        // fx-adapter begin: per-frame (the simulation step)
        for (int r = 0; plugin && r < fx->reactionCount(plugin); ++r) fx->continueReaction(plugin, r, kStep, nullptr);
        // fx-adapter end
        driver->beginScene(true, true, scene.fogColor);
        smgr->drawAll();
        // fx-adapter begin: per-frame (the smoke, after the scene, into the window, with its z-buffer)
        if (plugin && (o.smoke || frame + 1 < o.frames)) {
            fxViewDesc view = FX_DESC_INIT(fxViewDesc);
            std::memcpy(view.view, driver->getTransform(video::ETS_VIEW).pointer(), sizeof view.view);
            std::memcpy(view.proj, driver->getTransform(video::ETS_PROJECTION).pointer(), sizeof view.proj);
            const core::vector3df eye = scene.camera->getAbsolutePosition();
            std::memcpy(view.eye, &eye.X, sizeof view.eye);
            view.nearPlane = scene.camera->getNearValue();
            view.farPlane = scene.camera->getFarValue();
            view.width = int(o.width);
            view.height = int(o.height);
            // Irrlicht looks down +z and draws its D3D-style [0,1] projection under GL's default
            // clip control: left-handed, clipDepthZeroToOne left 0, depth from the window (0).
            view.handedness = FX_LEFT_HANDED;
            fx->renderView(plugin, &view);
        }
        // fx-adapter end
        gui->drawAll();
        driver->endScene();
        frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }

    if (!o.screenshot.empty()) {
        video::IImage* shot = driver->createScreenShot();
        const bool written = shot && driver->writeImageToFile(shot, o.screenshot.c_str());
        if (shot) shot->drop();
        if (!written) {
            std::fprintf(stderr, "irrlicht_host: could not write %s\n", o.screenshot.c_str());
            return 1;
        }
    }
    // For the package test: where the GUI label is, and a rectangle inside the crate in front of the smoke.
    const core::recti rects[2] = {scene.label->getAbsolutePosition(), occluderRect(device, scene)};
    for (int i = 0; i < 2; ++i) {
        const core::recti& r = rects[i];
        std::printf("%s %d %d %d %d\n", i == 0 ? "label_rect" : "occluder_rect", r.UpperLeftCorner.X,
                    r.UpperLeftCorner.Y, r.LowerRightCorner.X, r.LowerRightCorner.Y);
    }
    // The first frames build textures and the plugin's targets: the median of the rest.
    const size_t skip = std::min<size_t>(10, frameMs.size() / 2);
    std::vector<double> steady(frameMs.begin() + long(skip), frameMs.end());
    std::sort(steady.begin(), steady.end());
    if (!steady.empty()) {
        std::printf("frame_ms median %.3f over %zu frames (%s)\n", steady[steady.size() / 2], steady.size(),
                    !o.plugin ? "no plugin" : o.smoke ? "smoke" : "smoke, last frame without");
    }

    // fx-adapter begin: teardown (statistics, then destroy with the GL context still current)
    fxStats2 stats = FX_DESC_INIT(fxStats2);
    if (plugin) fx->stats2(plugin, &stats);
    std::printf("particles_alive %d api_errors %d\n", stats.particlesAlive, stats.apiErrors);
    if (plugin) fx->destroy(plugin);
    // fx-adapter end
    device->drop();
    return 0;
}
