// Mega-particles: fractal detail and light for the blurred cloud (included by fs_mega_blur.glsl
// under FX_MEGA_SHADE). Works in the spheres target's pixels; view space as everywhere else.

uniform mat4 uInvView;           // view -> world
uniform vec4 uProjTerms;         // proj[0][0], proj[1][1], proj[2][0], proj[2][1]
uniform float uTime;             // the reaction's simulation clock, s (pauses with the simulation)
uniform float uNoiseStrength;    // mega.noise_strength [0, 1]
uniform float uNoiseScale;       // mega.noise_scale, m: the largest feature
uniform int uLit;                // 0: unlit (ramp colour)
uniform vec3 uToSun;             // view space, unit
uniform vec3 uSunColor;
uniform vec3 uAmbient;           // host ambient x lighting.ambient
uniform float uScattering;       // lighting.scattering
uniform float uAnisotropy;       // lighting.anisotropy (Henyey-Greenstein g)
uniform float uAbsorption;       // lighting.absorption

// Value noise on the integer lattice (a hash of the cell corner, quintic-free smoothstep blend).
float megaHash(vec3 p) {
    p = fract(p * 0.3183099 + vec3(0.71, 0.113, 0.419));
    p *= 17.0;
    return fract(p.x * p.y * p.z * (p.x + p.y + p.z));
}

float megaValueNoise(vec3 x) {
    vec3 i = floor(x);
    vec3 f = fract(x);
    f = f * f * (3.0 - 2.0 * f);
    return mix(mix(mix(megaHash(i), megaHash(i + vec3(1, 0, 0)), f.x),
                   mix(megaHash(i + vec3(0, 1, 0)), megaHash(i + vec3(1, 1, 0)), f.x), f.y),
               mix(mix(megaHash(i + vec3(0, 0, 1)), megaHash(i + vec3(1, 0, 1)), f.x),
                   mix(megaHash(i + vec3(0, 1, 1)), megaHash(i + vec3(1, 1, 1)), f.x), f.y), f.z);
}

// Four octaves, each half the size and drifting its own way (slowly: 0.05-0.1 features/s), in
// [0, 1]. A function of world position and simulation time only: deterministic.
float megaFbm(vec3 p, float t) {
    float sum = 0.0, amplitude = 0.5;
    for (int o = 0; o < 4; ++o) {
        vec3 drift = vec3(0.06, 0.09, -0.05) * t * (1.0 + 0.35 * float(o));
        sum += amplitude * megaValueNoise(p + drift + vec3(17.3, 4.1, 9.7) * float(o));
        p = p * 2.03;
        amplitude *= 0.5;
    }
    return sum / 0.9375;
}

// Henyey-Greenstein phase times 4 pi (1 for an isotropic medium).
float megaPhase(float cosTheta, float g) {
    float g2 = g * g;
    return (1.0 - g2) / pow(max(1.0 + g2 - 2.0 * g * cosTheta, 1e-4), 1.5);
}

// `colour`: blurred (rgb x tau sums, depth); `density`: blurred (tau, normal.xy x tau, 0).
vec4 megaShade(vec4 colour, vec4 density, ivec2 p, ivec2 last) {
    float tau = density.x;
    float depth = colour.a;
    if (tau <= 1e-4 || depth <= 0.0) return vec4(0.0);
    float coverage = 1.0 - exp(-tau);
    vec2 ndc = (vec2(p) + 0.5) / vec2(last + 1) * 2.0 - 1.0;
    vec3 ray = vec3((ndc.x + uProjTerms.z) / uProjTerms.x, (ndc.y + uProjTerms.w) / uProjTerms.y, -1.0);
    vec3 viewPos = ray * depth;  // ray.z = -1
    vec3 world = (uInvView * vec4(viewPos, 1.0)).xyz;

    // Fractal noise eats into alpha: alpha is remapped from [e, 1] to [0, 1] with e the local
    // erosion, so the dense core stays solid and the soft blurred edge turns into puffs.
    float n = smoothstep(0.2, 0.8, megaFbm(world / uNoiseScale, uTime));
    float erosion = uNoiseStrength * (1.0 - n);
    float alpha = clamp((coverage - erosion) / max(1.0 - erosion, 1e-3), 0.0, 1.0);
    vec3 albedo = colour.rgb / tau;  // the tau-weighted ramp colour
    if (uLit == 0) return vec4(albedo * alpha, alpha);

    vec2 nxy = density.yz / tau;
    float len2 = dot(nxy, nxy);
    vec3 normal = len2 > 1.0 ? vec3(nxy / sqrt(len2), 0.0) : vec3(nxy, sqrt(1.0 - len2));
    vec3 toEye = normalize(-ray);
    // Wrap diffuse (light reaches round the puffs), Henyey-Greenstein forward scattering for the
    // rim toward the sun (thin parts glow most: weighted by 1 - 0.7 coverage).
    float wrap = clamp((dot(normal, uToSun) + 0.5) / 1.5, 0.0, 1.0);
    float phase = megaPhase(dot(-uToSun, toEye), uAnisotropy);
    float rim = 1.0 - 0.7 * coverage;
    // Thickness toward the sun: how deep below the cloud's sun-facing surface this pixel lies,
    // estimated from the optical depth through the cloud here (tau, along the view ray) and how
    // far the surface faces away from the sun (0 facing it, 1 edge-on, 2 facing away), so the
    // side away from the sun of a thick cloud darkens: exp(-absorption x thickness). (Marching the
    // blurred density toward the sun on screen instead showed the half-blurred input as bands.)
    float thickness = 0.25 * (1.0 - dot(normal, uToSun)) * min(tau, 6.0);
    float shadow = exp(-uAbsorption * thickness);
    vec3 sun = uSunColor * shadow * ((1.0 - uScattering) * wrap + uScattering * phase * rim);
    vec3 lit = albedo * (uAmbient + sun);
    return vec4(lit * alpha, alpha);
}
