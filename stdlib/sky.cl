//! fn shade_sky
//! deps: vec3_ops
//! class: estimate
// background.sky as seen along rd: zenith to horizon by the square root of
// the elevation, the horizon darkening to the ground below it, and a halo
// around the sun (its colours come from the host's sky model; an estimate
// of a daylight sky, not a spectral one). The sun itself is a light.
inline vec3 shade_sky(vec3 rd, vec3 up, vec3 sun, vec3 zenith, vec3 horizon, vec3 ground, vec3 glow, real glow_power)
{
    real e = v3_dot(rd, up);
    vec3 above = v3_mix(horizon, zenith, sqrt(clamp(e, K(0.0f), K(1.0f))));
    vec3 below = v3_mix(horizon, ground, clamp(-4.0f * e, K(0.0f), K(1.0f)));
    vec3 c = v3_select(below, above, e >= 0.0f);
    real cs = fmax(v3_dot(rd, sun), K(1e-6f));
    real halo = exp2(glow_power * log2(cs)) * clamp(1.0f + 8.0f * e, K(0.0f), K(1.0f));
    return v3_mad(c, glow, halo);
}
