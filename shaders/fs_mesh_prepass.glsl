// Depth prepass: the z-buffer, plus linear view-space depth (metres, positive) in an R32F target
// for soft particles. 32-bit float keeps centimetres at 10 km even with near = 0.01.
in vec3 vNormal;
in vec3 vViewPos;

layout(location = 0) out float oLinearDepth;

void main() {
    oLinearDepth = -vViewPos.z;
}
