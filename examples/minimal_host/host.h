#pragma once
// The minimal host's pieces: a context (osmesa_context.cpp), a few GL helpers with the host's
// own glad (host_gl.cpp) and the frame logic (main.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

bool createContext();
void destroyContext();
void* procAddress(const char* name);

/// Loads the host's own global glad. False when the context offers no GL 3.3 core.
bool loadHostGl();

/// A colour target (RGBA8 or R32F) with a depth buffer of its own or borrowed.
struct HostTarget {
    uint32_t fbo = 0, color = 0, depth = 0;
    int width = 0, height = 0;
    bool linearDepth = false;  // R32F linear depth instead of RGBA8 colour
};
HostTarget makeTarget(int width, int height, bool linearDepth, uint32_t sharedDepth);
void deleteTarget(HostTarget& t);
void bindTarget(const HostTarget& t);

/// Draws the ground plane (y = 0, 80 m square) with a wall behind the car into `t`: grey shaded
/// colour, or linear view depth (metres) into an R32F target.
void drawScene(const HostTarget& t, const glm::mat4& view, const glm::mat4& proj);

/// A few GL state values the plugin promises to restore, as text (compared before/after).
std::string glStateFingerprint();
int glErrors();
std::vector<uint8_t> readPixels(const HostTarget& t);  // RGBA8, top row first
