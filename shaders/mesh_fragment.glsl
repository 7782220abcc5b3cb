// The opaque mesh fragment shaders' interface (fs_mesh.glsl, fs_mesh_costly.glsl): what
// vs_mesh.glsl hands them and the two targets they write.
in vec3 vNormal;
in vec3 vViewPos;
in vec3 vWorldPos;

layout(location = 0) out vec4 oColor;
// Linear view depth (metres) for a second render target: where the opaque pass also writes the
// scene depth the particles read (no depth prepass). Without one bound the output is dropped.
layout(location = 1) out float oLinearDepth;
