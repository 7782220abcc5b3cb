// Range [lo, hi] of slopes (offset / depth) of the rays that meet a disc of radius r centred
// `a` across and `depth` ahead in one axis plane (a sphere's x/depth slopes are those of its
// projection onto the xz plane, a disc of the same radius), widened by `margin` on each bounded
// side and clamped to +-smax; an unbounded side (camera inside the disc, tangent at or behind 90
// degrees) is +-smax. The screen boxes of spherical particles (vs_particles.glsl, FX_SPHERICAL)
// and of mega-particles (vs_mega.glsl).
vec2 slopeRange(float a, float depth, float r, float smax, float margin) {
    float len2 = a * a + depth * depth;
    if (len2 <= r * r * 1.0001) return vec2(-smax, smax);
    const float kLimit = 1.5697963;  // just under pi/2
    float centre = atan(a, depth);
    float halfAngle = asin(clamp(r / sqrt(len2), 0.0, 1.0));
    float lo = centre - halfAngle, hi = centre + halfAngle;
    if (lo >= kLimit) return vec2(smax);   // wholly beside/behind the eye on this axis
    if (hi <= -kLimit) return vec2(-smax);
    float slo = lo <= -kLimit ? -smax : tan(lo) - margin;
    float shi = hi >= kLimit ? smax : tan(hi) + margin;
    return clamp(vec2(slo, shi), -smax, smax);
}
