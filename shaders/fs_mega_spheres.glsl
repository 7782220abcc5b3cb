#version 330 core
// Mega-particles, spheres pass: the ray through this pixel against the particle's sphere, its
// chord clipped to [near plane, scene depth], where the scene depth is the nearest of the
// full-resolution pixels this reduced-resolution pixel covers (fs_mega_depth.glsl): a sphere
// whose front lies behind the scene adds nothing. Every sphere is summed, order-independently
// (blend ONE, ONE; equation ADD for colour, MAX for alpha):
//   tau = uDensity x ramp alpha x life fade x (visible chord / diameter)   optical depth
//   output 0 (RGBA16F): (sum of ramp rgb x tau, max(-front depth))  -> nearest sphere front
//   output 1 (RGBA16F): (sum of tau, sum of normal.xy x tau, 0)     -> density-weighted normal
// so the pixel's coverage is 1 - exp(-sum tau) (1 where a dense sphere is hit through its
// middle, fading to 0 at a sphere's rim), its colour the tau-weighted ramp colour, its normal
// the tau-weighted view-space normal of the spheres' fronts (z rebuilt as sqrt(1 - x^2 - y^2):
// fronts face the camera) and its depth the nearest front of any sphere that adds at least
// kMinTau (a dying sphere does not move the cloud's surface). Output 0 is cleared to alpha
// -65504: no sphere. A camera inside a sphere sees its front at the near plane, facing it.
// Summing instead of keeping the nearest sphere means a faint sphere in front never hides the
// dense cloud behind it, and the cloud thickens where spheres overlap.
in vec3 vViewPos;
flat in vec4 vSphere;
flat in vec4 vColor;

uniform sampler2D uMegaDepth;  // R32F, this target's size: nearest scene depth per pixel
uniform float uNear;
uniform float uDensity;        // optical depth of a sphere of alpha 1 through its centre

layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oDensity;

const float kMinTau = 0.02;

void main() {
    vec3 dir = normalize(vViewPos);
    float depthPerMetre = max(-dir.z, 1e-4);
    vec3 centre = vSphere.xyz;
    float r = vSphere.w;
    float tMid = dot(centre, dir);
    vec3 offset = dir * tMid - centre;
    float d2 = dot(offset, offset);
    if (d2 >= r * r) discard;
    float halfChord = sqrt(r * r - d2);
    float scene = texelFetch(uMegaDepth, ivec2(gl_FragCoord.xy), 0).r;
    if (scene <= 0.0) scene = 3.0e38;  // nothing drawn (fx/HostAdapter.h)
    float tFront = tMid - halfChord;
    float t0 = max(tFront, uNear / depthPerMetre);
    float t1 = min(tMid + halfChord, scene / depthPerMetre);
    if (t1 <= t0) discard;  // behind the scene or the camera
    float tau = uDensity * vColor.a * (t1 - t0) / (2.0 * r);
    vec3 normal = tFront < t0 ? -dir : (dir * t0 - centre) / r;
    float depth = min(t0 * depthPerMetre, 60000.0);  // half floats end at 65504
    oColor = vec4(vColor.rgb * tau, tau >= kMinTau ? -depth : -65504.0);
    oDensity = vec4(tau, normal.xy * tau, 0.0);
}
