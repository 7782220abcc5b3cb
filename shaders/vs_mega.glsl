#version 330 core
// Mega-particles, spheres pass (seed 001; fx_plugin/render/MegaRenderer.h): one screen-space box
// per particle that covers every view ray meeting its sphere; fs_mega_spheres.glsl intersects
// the rays. Same instance streams as the billboards (render/InstanceStream.h).
//
// The sphere's radius is size / 2. Its colour and alpha come from the reaction's colour ramp at
// the particle's life; the alpha times the life fade is its density (fs_mega_spheres.glsl).
layout(location = 0) in vec2 aCorner;            // (+-1, +-1), triangle strip order
layout(location = 1) in vec4 aPosSize;           // centre (world, m), size (m)
layout(location = 2) in vec4 aLifeRotFadeFrame;  // life [0,1], rotation, fade [0,1], frame

uniform mat4 uView;
uniform mat4 uProj;
uniform float uNear;
uniform float uFar;
uniform vec2 uSlopeMax;       // |x/depth|, |y/depth| just past the frustum edges
uniform sampler2D uRamp;      // colour by life, one row per reaction (ColorRampTexture)
uniform float uRampRow;

out vec3 vViewPos;
flat out vec4 vSphere;        // view-space centre, radius
flat out vec4 vColor;         // ramp colour, alpha = ramp alpha x life fade

const float kRampTexels = 64.0;  // ColorRampTexture::kTexels

// slopeRange(), with no margin.
#include "particles_sphere_bounds.glsl"

void main() {
    float life = clamp(aLifeRotFadeFrame.x, 0.0, 1.0);
    vColor = texture(uRamp, vec2((life * (kRampTexels - 1.0) + 0.5) / kRampTexels, uRampRow));
    vColor.a *= clamp(aLifeRotFadeFrame.z, 0.0, 1.0);
    float radius = 0.5 * aPosSize.w;
    vec3 centre = (uView * vec4(aPosSize.xyz, 1.0)).xyz;
    float depth = -centre.z;
    vec2 sx = slopeRange(centre.x, depth, radius, uSlopeMax.x, 0.0);
    vec2 sy = slopeRange(centre.y, depth, radius, uSlopeMax.y, 0.0);
    // The box lies at the sphere's front (clamped into the clip range); the fragment shader
    // only uses the ray direction, so its depth changes no pixel.
    float quadDepth = clamp(depth - radius, uNear * 1.01, uFar * 0.99);
    vec2 slope = vec2(aCorner.x < 0.0 ? sx.x : sx.y, aCorner.y < 0.0 ? sy.x : sy.y);
    vec3 viewPos = vec3(slope * quadDepth, -quadDepth);
    vSphere = vec4(centre, radius);
    vViewPos = viewPos;
    gl_Position = uProj * vec4(viewPos, 1.0);
}
