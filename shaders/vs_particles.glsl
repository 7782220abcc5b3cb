#version 330 core
// Instanced particles, billboarded here (000 section 2.5 / 3.3.3): stream 0 is the shared
// corners, stream 1 one record per particle (InstanceStream.h describes the layout).
//
// Billboards (hard, soft): view-plane-aligned, edge `size` around the centre, built from the
// camera right/up vectors read out of the view matrix. The texture coordinate is the corner
// rotated by the particle's angle (000 section 3.3.6). Quads (uTrimmed 0) draw the four corners
// of stream 0 as a strip. Trimmed (uTrimmed 1, a fan of 8): the corners are the atlas frame's
// polygon from uShapes (render/TrimmedShapes.h), given in texture space and turned back by the
// angle, so texture coordinates are exactly those of the quad and only the transparent area is
// left out. The polygon's LOD bucket comes from the particle's texels per pixel (a billboard
// facing the camera has one isotropic LOD), half a level coarser than the sampler will use.
//
// FX_SPHERICAL: the quad only has to cover every view ray that meets the particle sphere
// (radius size/2); the fragment shader intersects each ray with the sphere. Per screen axis the
// exact range of ray slopes through the sphere is computed; where it is unbounded (camera inside
// or beside the sphere) it extends to the frustum edge, so a camera inside a particle still gets
// a screen-covering quad. The quad lies at the sphere's front (its nearest depth, clamped into the
// clip range): the fragment shader only uses the ray direction, so the plane's depth changes no
// pixel, and a host z-buffer test against it is conservative: a fragment whose sphere front is
// behind the scene sees no chord, so nothing visible is ever rejected.
// Trimmed spheres (uTrimmed 1) draw the atlas frame's polygon clipped to the unit disc
// (uShapes holds TrimmedShapes' Clip::Disc table for these programs), carried onto the screen
// through the plane tangent to the sphere at its centre's direction; sphereTrimVertex() says why
// that holds every pixel with alpha. Where its bounds do not hold (a large or very oblique
// sphere) they draw the octagon around the sphere's outline, and the box when the camera is
// close to or inside it.
#include "particles_common.glsl"

layout(location = 0) in vec2 aCorner;            // (+-1, +-1), triangle strip order
layout(location = 1) in vec4 aPosSize;           // centre (world, m), size (m)
layout(location = 2) in vec4 aLifeRotFadeFrame;  // life [0,1], rotation (rad), fade [0,1], frame

const int kShapeVertices = 8;  // TrimmedShapes::kMaxVertices
// Spheres' bounds (box, octagon, polygon) reach this many pixels past the sphere's outline:
// the rasteriser snaps vertices to a sub-pixel grid (1/256 px on llvmpipe), and a bound that
// only touches the outline loses the odd rim pixel to that rounding.
const float kSnapMarginPixels = 1.0 / 16.0;
uniform int uTrimmed;          // 1: draw the frame's trimmed polygon (a fan of kShapeVertices)
uniform int uShapeBuckets;     // LOD buckets per frame in uShapes
uniform float uLodScale;       // texels per pixel = uLodScale * depth / size
uniform vec4 uShapes[128];     // [frame][bucket][vertex] (x, y), two vertices per vec4
uniform float uPixelSlope;     // spherical: one pixel of the target in ray slope
uniform vec4 uShapeInfo[16];   // spherical: [frame][bucket] (inradius, area / 4) of each disc polygon, two per vec4

#define FX_VARYING out
#include "particles_varyings.glsl"

// The trimmed polygon's vertex gl_VertexID for a particle whose texture maps `texelsPerPixel`
// texels of level 0 onto a pixel (its LOD bucket: TrimmedShapes.h), and that polygon's index
// into uShapes' [frame][bucket] table.
vec2 shapeVertex(float frame, float texelsPerPixel, out int polygon) {
    float lod = log2(max(texelsPerPixel, 1e-6));
    int bucket = clamp(int(ceil(lod + 0.5)), 0, uShapeBuckets - 1);
    polygon = clamp(int(frame + 0.5), 0, 3) * uShapeBuckets + bucket;
    int index = polygon * kShapeVertices + min(gl_VertexID, kShapeVertices - 1);
    vec4 pair = uShapes[index / 2];
    return (index % 2) == 0 ? pair.xy : pair.zw;
}

#ifdef FX_SPHERICAL
// Trimmed sphere, vertex gl_VertexID: the ray slope (x/depth, y/depth) of the disc polygon's
// vertex, or false where this particle's bounds do not hold (every vertex of a particle decides
// alike: the test only reads per-particle values).
//
// The fragment shader looks the atlas up at o.xy / r, o the ray's closest approach to the centre
// c minus c. Carry each ray onto the plane through c perpendicular to c, at offset tau from c:
// the plane's rays are a projective map of tau (lines stay lines on the screen) and tau.xy a
// linear one. Exactly, o = tau / (1 + rho^2) - |c| rho^2 / (1 + rho^2) * c / |c|, rho = |tau| / |c|
// <= tan A (A the sphere's angular radius). So for every ray of the sphere
//   tau.xy = (1 + rho^2) (o.xy + mu * c.xy / |c|),  0 <= mu <= r sin A:
// tau.xy lies in the polygon (in o.xy) shifted by half that segment, grown by the other half
// (scaled about the shifted centre by 1 + half / inradius), then scaled by 1 + tan^2 A. Mapped
// linearly onto the plane, that polygon holds every ray whose o.xy lies in the original one.
// Brute force over 2.3e7 rays (off-axis up to 75 degrees, sin A up to 0.45) found none outside
// it, and some outside with 10 % less growth: the bound is tight, 20 % is kept to spare. The
// lookup's LOD is at most log2(1 + r / depth) above a billboard's at the centre's depth (also
// checked by brute force): one more margin on the bucket.
bool sphereTrimVertex(vec3 centre, float dist, float radius, float frame, float size, vec2 turn, out vec2 slope) {
    float depth = -centre.z;
    float sinA = radius / dist;
    if (depth <= 0.0 || sinA > 0.4) return false;
    int polygon;
    vec2 local = shapeVertex(frame, uLodScale * depth / max(size, 1e-6) * (1.0 + 1.25 * radius / depth), polygon);
    vec4 infoPair = uShapeInfo[polygon / 2];
    vec2 info = (polygon % 2) == 0 ? infoPair.xy : infoPair.zw;
    float inradius = info.x;
    if (inradius < 0.05) return false;
    float sinOff = length(centre.xy) / dist;
    vec2 halfShift = 0.5 * radius * sinA * centre.xy / dist;
    // A plane offset of d moves a ray's slope by at least d / dist.
    float snap = kSnapMarginPixels * uPixelSlope / (sinA * inradius);
    float grow = 1.0 + 1.2 * 0.5 * sinA * sinOff / inradius + snap;
    float stretch = 1.0 + 1.2 * sinA * sinA / (1.0 - sinA * sinA);  // 1 + tan^2 A
    // Where the margins make it larger than the octagon around the sphere's cone (area
    // 3.31 (|c| tan A)^2 on the same plane, in units of r^2 3.31 / cos^2 A), the octagon is the
    // better bound: near, oblique spheres.
    if (4.0 * info.y * stretch * stretch * grow * grow >= 3.3137085 / (1.0 - sinA * sinA)) return false;
    // The plane point's depth offset stays within half the centre's depth: its rays point ahead.
    if (stretch * (length(halfShift) + 1.415 * grow * radius) * length(centre.xy) >= 0.5 * depth * depth) return false;
    vec2 o = stretch * (halfShift + grow * radius * turnBack(local, turn));
    vec3 onPlane = vec3(centre.xy + o, centre.z - dot(o, centre.xy) / centre.z);
    slope = onPlane.xy / -onPlane.z;
    return true;
}

// slopeRange(): the sphere's screen box, widened by kSnapMarginPixels.
#include "particles_sphere_bounds.glsl"
#endif

void main() {
    vec4 ramp = texture(uRamp, vec2(rampU(aLifeRotFadeFrame.x), uRampRow));
    float fade = aLifeRotFadeFrame.z;
    vOpacity = ramp.a * fade;
    vCell = atlasCell(aLifeRotFadeFrame.w);
    vTurn = vec2(cos(aLifeRotFadeFrame.y), sin(aLifeRotFadeFrame.y));
    float radius = 0.5 * aPosSize.w;

#ifdef FX_SPHERICAL
    vec3 centre = (uView * vec4(aPosSize.xyz, 1.0)).xyz;
    float depth = -centre.z;
    vec2 sx = slopeRange(centre.x, depth, radius, uSlopeMax.x, kSnapMarginPixels * uPixelSlope);
    vec2 sy = slopeRange(centre.y, depth, radius, uSlopeMax.y, kSnapMarginPixels * uPixelSlope);
    float quadDepth = clamp(depth - radius, uNear * 1.01, uFar * 0.99);
    vec2 corner = aCorner;
    if (uTrimmed != 0) {
        // A fan of 8: the box's corners in fan order (the last one repeated) unless the octagon
        // below applies. gl_VertexID 0..3 -> (-1,-1), (1,-1), (1,1), (-1,1).
        int k = min(gl_VertexID, 3);
        corner = vec2(k == 1 || k == 2 ? 1.0 : -1.0, k >= 2 ? 1.0 : -1.0);
    }
    vec2 slope = vec2(corner.x < 0.0 ? sx.x : sx.y, corner.y < 0.0 ? sy.x : sy.y);
    float dist = length(centre);
    if (uTrimmed != 0 && dist > radius * 1.0001) {
        vec2 trimmedSlope;
        if (sphereTrimVertex(centre, dist, radius, aLifeRotFadeFrame.w, aPosSize.w, vTurn, trimmedSlope)) {
            slope = trimmedSlope;
        } else {
            // The regular octagon around the cone of rays that touch the sphere (angle
            // asin(r / dist) around the centre's direction), circumscribed: each vertex
            // direction is the axis plus tan(angle) / cos(pi / 8) sideways. Projected centrally
            // onto the quad's plane it still holds the sphere's outline (lines stay lines) while
            // covering 0.83 of the box. Only when every vertex ray points clearly forward; else
            // the box.
            vec3 axis = centre / dist;
            float sinA = radius / dist;
            float spread = (sinA / sqrt(max(1.0 - sinA * sinA, 1e-12)) + kSnapMarginPixels * uPixelSlope) * 1.0823922;  // 1 / cos(pi/8)
            vec3 u = normalize(abs(axis.x) < 0.9 ? cross(axis, vec3(1.0, 0.0, 0.0)) : cross(axis, vec3(0.0, 1.0, 0.0)));
            vec3 v = cross(axis, u);
            float worstZ = axis.z + spread * length(vec2(u.z, v.z));
            if (worstZ < -0.05) {
                float angle = (float(min(gl_VertexID, 7)) + 0.5) * 0.78539816;  // 2 pi / 8
                vec3 dir = axis + spread * (cos(angle) * u + sin(angle) * v);
                slope = dir.xy / -dir.z;
            }
        }
    }
    vec3 viewPos = vec3(slope * quadDepth, -quadDepth);
    vSlope = slope;
    vSphere = vec4(centre, radius * radius);
    sphereAtlasMap(vTurn, radius, vCell, vAtlasMap, vAtlasBase);
    vLocal = vec2(0.0);
    vAtlasUV = vec2(0.0);
    vFadeLine = vec3(0.0);
#else
    vec3 right = normalize(vec3(uView[0][0], uView[1][0], uView[2][0]));
    vec3 up = normalize(vec3(uView[0][1], uView[1][1], uView[2][1]));
    vec2 corner = aCorner;
    vec2 local = rotate2(aCorner, aLifeRotFadeFrame.y);
    if (uTrimmed != 0) {
        float centreDepth = max(-(uView * vec4(aPosSize.xyz, 1.0)).z, uNear);
        int polygon;
        local = shapeVertex(aLifeRotFadeFrame.w, uLodScale * centreDepth / max(aPosSize.w, 1e-6), polygon);
        corner = rotate2(local, -aLifeRotFadeFrame.y);
    }
    vec3 world = aPosSize.xyz + (corner.x * right + corner.y * up) * radius;
    vec3 viewPos = (uView * vec4(world, 1.0)).xyz;
    vSphere = vec4(0.0);
    vSlope = vec2(0.0);
    vAtlasMap = vec4(0.0);
    vAtlasBase = vec2(0.0);
    vLocal = local;
    vAtlasUV = atlasUVOf(local, vCell);
#endif
    vViewPos = viewPos;
#ifdef FX_SPHERICAL
    vec4 fog = particleFog(-centre.z);
    particleTint(ramp, fade, fog, vTint, vFogAdd);  // the near fade: per fragment, at the chord
#else
    // A billboard lies at one depth, so its fog and its near fade are the particle's own: the
    // near fade scales its output as the life fade does, and goes into the tint with it.
    vec4 fog = particleFog(-viewPos.z);
    particleTint(ramp, fade * nearFadeFactor(-viewPos.z), fog, vTint, vFogAdd);
    vFadeLine = softFadeLine(-viewPos.z);  // and so is its soft fade's line
#endif
#ifdef FX_LIT
#ifdef FX_SPHERICAL
    vec3 lightAt = centre;   // the quad lies at the sphere's front: light the sphere as a whole
#else
    vec3 lightAt = viewPos;  // the billboard's corner
#endif
    vSunLight = sunThroughSmoke(lightAt);
    vPhase = phaseHG(lightAt);
    // The fragment bends its normal by the atlas's, turned by vTurn: the normal strength (and for
    // spheres the bump scale 0.6 and the radius) go in here, once (billboardNormal, the
    // spherical fragment shader).
#ifdef FX_SPHERICAL
    vTurn *= uNormalStrength * 0.6 * radius;
#else
    vTurn *= uNormalStrength;
#endif
#endif
    gl_Position = uProj * vec4(viewPos, 1.0);
}
