// What vs_particles.glsl hands the particle fragment shaders (fs_particles_hard, _soft,
// _spherical, _opacity), declared once for both sides: vs_particles defines FX_VARYING as `out`
// before including this, the fragment shaders include it as it is (`in`) and read the ones they
// need.
#ifndef FX_VARYING
#define FX_VARYING in
#endif
FX_VARYING vec3 vViewPos;       // view-space position on the quad
FX_VARYING vec2 vLocal;         // billboards: rotated particle-space coordinate, [-1,1]^2 inside the quad
FX_VARYING vec2 vAtlasUV;       // billboards: atlasUVOf(vLocal, vCell), worked out per vertex
FX_VARYING vec2 vSlope;         // spherical: the view ray through the pixel per metre of depth (x, y)
flat FX_VARYING vec4 vTint;     // the particle's colour, opacity, blend and fog (particleTint)
flat FX_VARYING vec3 vFogAdd;   // the fog colour its coverage adds (particleTint)
flat FX_VARYING float vOpacity; // ramp alpha x life fade: its share of the smoke's opacity map
flat FX_VARYING vec2 vCell;     // atlas coordinate of the frame's corner (atlasCell)
flat FX_VARYING vec4 vSphere;   // spherical: view-space centre, radius squared
flat FX_VARYING vec2 vTurn;     // (cos, sin) of the particle's angle
flat FX_VARYING vec4 vAtlasMap;  // spherical: the atlas coordinate as an affine map of the offset (sphereAtlasMap)
flat FX_VARYING vec2 vAtlasBase;
flat FX_VARYING vec3 vFadeLine;  // billboards: softFadeLine at the particle's depth
#ifdef FX_LIT
FX_VARYING vec3 vSunLight;      // sun colour x transmittance through the smoke toward the sun
FX_VARYING float vPhase;        // Henyey-Greenstein x 4 pi toward the eye
#endif
