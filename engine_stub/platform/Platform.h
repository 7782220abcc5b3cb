#pragma once
// A GL 3.3 core context plus, for windows, a surface and input. Three backends: OSMesa (headless,
// the default: runs anywhere, llvmpipe), EGL surfaceless (headless on a real GPU) and GLFW (window).
// The engine never draws to the default framebuffer directly: it renders into render targets and
// presents by blitting (see rtt/), so a surfaceless context works the same as a window.
#include <memory>
#include <string>
#include <vector>

namespace cube {

enum class Backend { OSMesa, EGL, GLFW };

const char* backendName(Backend backend);
/// Parses "osmesa" | "egl" | "glfw"; false on anything else.
bool parseBackend(const std::string& text, Backend* out);

/// Defaults: OSMesa, 1280x1024, hidden, debug context on.
struct PlatformDesc {
    Backend backend = Backend::OSMesa;
    int width = 1280;
    int height = 1024;
    bool debugContext = true;
    std::string title = "cube_game";
};

/// Keys the game reacts to in a window (prepass-EQUAL, quarter-res, mode switches...).
enum class Key { P, Q, M, H, B, E, Escape, Count };

/// Keys a UI needs beyond text (which arrives as Char events). Platform-neutral numbering.
enum class UiKey { Tab, Left, Right, Up, Down, PageUp, PageDown, Home, End, Delete, Backspace,
                   Enter, Escape, A, C, V, X, Y, Z, Ctrl, Shift, Alt, Count };

/// One input event for a UI (the tweak panel), in window pixels from the top-left. The window
/// back end queues them; tests build them by hand and inject them into the same queue.
/// Defaults: a mouse move to (0, 0).
struct InputEvent {
    enum class Type { MouseMove, MouseButton, Scroll, Key, Char };
    Type type = Type::MouseMove;
    float x = 0.0f, y = 0.0f;  ///< MouseMove: position; Scroll: wheel steps (y up = positive)
    int button = 0;            ///< MouseButton: 0 left, 1 right, 2 middle
    bool down = false;         ///< MouseButton, Key: pressed (true) or released
    UiKey key = UiKey::Tab;    ///< Key
    unsigned codepoint = 0;    ///< Char: a Unicode code point typed
};

class Platform {
public:
    /// Makes a context and loads GL. On failure returns null and says why in `error`
    /// (no crash, no exit: the caller decides).
    static std::unique_ptr<Platform> create(const PlatformDesc& desc, std::string* error);
    virtual ~Platform() = default;

    virtual Backend backend() const = 0;
    /// Current framebuffer size; a minimised window reports 0x0.
    virtual int width() const = 0;
    virtual int height() const = 0;
    /// Shows the default framebuffer (swap for windows; nothing headless).
    virtual void present() = 0;
    /// Pumps window events; false once the window was asked to close.
    virtual bool pollEvents() = 0;
    /// True once per press of `key` since the last poll (edge, not level).
    virtual bool keyPressed(Key key) = 0;
    /// Moves the UI input events queued since the last call to the end of `out`, oldest first.
    /// Headless back ends have none.
    virtual void takeInputEvents(std::vector<InputEvent>* out) { (void)out; }
    /// Headless backends resize their default surface on request; windows follow the user.
    virtual void resize(int width, int height) = 0;
    /// The context's GL entry point lookup (for a plugin that loads GL itself).
    virtual void* getProcAddress(const char* name) const = 0;
    /// GL_RENDERER string, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    virtual std::string rendererName() const = 0;
    /// True when the driver renders in software (llvmpipe, softpipe, swrast): GPU timer
    /// queries are then meaningless and timing uses a CPU clock around glFinish.
    bool softwareRenderer() const;
};

/// What the headless back ends (OSMesa, EGL) share: the size they were last given, no window to
/// present or poll, no keys, and the GL_RENDERER string read once the context was made.
class HeadlessPlatform : public Platform {
public:
    int width() const override { return width_; }
    int height() const override { return height_; }
    void present() override {}
    bool pollEvents() override { return true; }
    bool keyPressed(Key) override { return false; }
    std::string rendererName() const override { return renderer_; }

protected:
    int width_ = 0, height_ = 0;
    std::string renderer_;
};

/// Keeps memory the process frees for reuse instead of returning it to the kernel at once
/// (glibc's mmap and trim thresholds). Platform::create calls it for a software renderer, whose
/// per-frame driver allocations would otherwise be page-faulted in anew every frame. A no-op
/// outside glibc.
void retainFreedMemory();

// Backend factories, one translation unit each (GL/osmesa.h, EGL and glad must not meet).
/// A new back end P initialised by P::init(desc, error); null (and *error set) when that fails.
template <class P>
std::unique_ptr<Platform> initialisedPlatform(const PlatformDesc& desc, std::string* error) {
    auto p = std::make_unique<P>();
    if (!p->init(desc, error)) return nullptr;
    return p;
}

std::unique_ptr<Platform> createOSMesaPlatform(const PlatformDesc& desc, std::string* error);
std::unique_ptr<Platform> createEGLPlatform(const PlatformDesc& desc, std::string* error);
std::unique_ptr<Platform> createGLFWPlatform(const PlatformDesc& desc, std::string* error);

/// Loads GL entry points through `getProc` (glad), checks for 3.3 core and hooks up KHR_debug.
/// Defined in gl/GlLoader.cpp, the only engine file besides gl/ users that sees glad's gl.h.
using GetProcFn = void* (*)(const char* name);
bool loadGL(GetProcFn getProc, std::string* error);

}  // namespace cube
