//! fn fx_fract
//! class: helper
// The fractional part (OpenCL's fract() wants a pointer for the integer part).
inline real fx_fract(real x) { return x - floor(x); }

//! fn fx_hash
//! deps: fx_fract
//! class: helper
// A pseudo-random number in [0, 1) from three reals, e.g. pixel x, y and a
// seed (Hoskins' "hash without sine" hash13). Deterministic per pixel, so a
// tiled render equals an untiled one.
inline real fx_hash(real a, real b, real c)
{
    real x = fx_fract(a * 0.1031f), y = fx_fract(b * 0.1031f), z = fx_fract(c * 0.1031f);
    real d = x * (z + 31.32f) + y * (y + 31.32f) + z * (x + 31.32f);
    x += d; y += d; z += d;
    return fmin(fx_fract((x + y) * z), K(0.99999994f));
}

//! fn fx_tent
//! class: helper
// Maps u in [0, 1) to an offset in (-1, 1) distributed as a tent: sampling
// with it and equal weights is a tent filter two pixels wide.
inline real fx_tent(real u)
{
    real a = sqrt(2.0f * u) - 1.0f;
    real b = 1.0f - sqrt(fmax(2.0f - 2.0f * u, K(0.0f)));
    return SEL(b, a, u < 0.5f);
}

//! fn march_sphere_trace_closest
//! deps: vec3_ops, march_advance
//! after-scene
//! class: helper
// march_sphere_trace that also returns the closest approach (the smallest
// distance seen), which glow needs; a separate function so scenes without
// glow do not pay for the extra min per step.
inline mask march_sphere_trace_closest(TIME_PARAM vec3 ro, vec3 rd, real t0, real t1, mask active,
                                       real pixel_angle, real hit_eps, real step_factor,
                                       int max_steps, real* t_out, real* steps, real* closest)
{
    real t = t0;
    mask hit = active & !active;
    real n = 0.0f;
    real c = (real)(1e30f);
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = scene_dist_inline(TIME_ARG v3_mad(ro, rd, t), active);
        c = SEL(c, fmin(c, d), active);
        march_advance(d, t1, pixel_angle, hit_eps, step_factor, &t, &active, &hit, &n);
    }
    *t_out = t;
    *steps = n;
    *closest = c;
    return hit;
}

//! fn shadow_hard
//! deps: vec3_ops
//! after-scene
//! class: helper
// 0 where something lies between p and the light along l within [tmin, tmax],
// else 1. tmin > 0 steps off the surface the ray starts on; eps is the hit
// distance; every step advances at least min_step so the march ends.
inline real shadow_hard(TIME_PARAM vec3 p, vec3 l, real tmin, real tmax, real eps, real min_step,
                        int max_steps, mask active)
{
    real lit = 1.0f;
    real t = tmin;
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = scene_dist_inline(TIME_ARG v3_mad(p, l, t), active);
        mask blocked = active & (d < eps);
        lit = SEL(lit, (real)(0.0f), blocked);
        active = active & !blocked;
        t = SEL(t, t + fmax(d, min_step), active);
        active = active & (t < tmax);
    }
    return lit;
}

//! fn shadow_soft
//! deps: vec3_ops
//! after-scene
//! class: estimate
// Quilez's penumbra estimate: the smallest k * d / t along the shadow ray,
// clamped to [0, 1]; larger k gives sharper shadows. Steps are capped at a
// quarter of t (and at least min_step), so the closest approach is sampled
// closely wherever it falls (a tighter cap needs more steps than the default
// budget of 64 and lets light leak through crevices). Uncapped steps (or Quilez's
// triangulation between two steps, which assumes an exact distance) sample
// it at positions that jump from pixel to pixel when the distance is a
// fractal's estimate: concentric rings in the penumbra that no step budget
// removes. t starts at tmin > 0, so it never divides by 0.
inline real shadow_soft(TIME_PARAM vec3 p, vec3 l, real tmin, real tmax, real k, real eps, real min_step,
                        int max_steps, mask active)
{
    real res = 1.0f;
    real t = tmin;
    const real inv_k1 = 1.0f / (k + 1.0f);  // for the whole steps below
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = scene_dist_inline(TIME_ARG v3_mad(p, l, t), active);
        res = SEL(res, fmin(res, k * d / t), active);
        res = SEL(res, (real)(0.0f), active & (d < eps));
        active = active & (d >= eps) & (res > 0.002f);
        real cap = fmax(0.25f * t, 4.0f * min_step);
        // Within s of here the distance is at least d - s, so k * d / t stays
        // at or above res for any s up to (k d - res t) / (k + res): such a
        // step cannot lower the minimum, and rays leaving the surface in the
        // open take it whole (res <= 1 makes k + 1 a safe divisor, known
        // before the loop).
        real skip = (k * d - res * t) * inv_k1;
        t = SEL(t, t + clamp(d, min_step, fmax(cap, skip)), active);
        active = active & (t < tmax);
    }
    return clamp(res, K(0.0f), K(1.0f));
}

//! fn ao_normal_samples
//! deps: vec3_ops
//! after-scene
//! class: estimate
// Ambient occlusion from distance probes along the normal (seed 001 part II):
// in the open, the distance at height h above the surface is h; any shortfall
// means nearby geometry. Nearer probes weigh more. 1 = unoccluded.
// A probe counts only where the distance is below its height h, so it asks
// for no more (scene_dist_probe: an object set's walk skips the boxes
// farther than h), and only for the `live` lanes, whose values are used.
inline real ao_normal_samples(TIME_PARAM vec3 p, vec3 n, int samples, real distance, real strength, mask live)
{
    real occ = 0.0f;
    real w = 1.0f, wsum = 0.0f;
    for (int i = 1; i <= samples; ++i) {
        real h = distance * (real)((scalar)i / (scalar)samples);
        real d = scene_dist_probe(TIME_ARG v3_mad(p, n, h), h, live);
        occ += w * fmax(h - d, K(0.0f)) / h;
        wsum += w;
        w *= 0.7f;
    }
    return clamp(1.0f - strength * occ / wsum, K(0.0f), K(1.0f));
}

//! fn ao_step_count
//! class: estimate
// Ambient occlusion from the march's step count (seed 001 part II): rays that
// needed many steps passed close to geometry, which happens in creases.
inline real ao_step_count(real steps, real max_steps, real strength)
{
    return clamp(1.0f - strength * steps / max_steps, K(0.0f), K(1.0f));
}

//! fn fog_exponential
//! deps: vec3_ops
//! class: helper
// Uniform exponential fog: the fraction exp(-density t) of c survives.
inline vec3 fog_exponential(vec3 c, vec3 fog_color, real t, real density)
{
    return v3_mix(fog_color, c, exp(-density * t));
}

//! fn fog_height
//! deps: vec3_ops
//! class: helper
// Exponential fog whose density falls with height: density(h) =
// density * exp(-falloff (h - base)); the optical depth is its integral along
// the ray, with the series limit where the ray runs level.
inline vec3 fog_height(vec3 c, vec3 fog_color, vec3 ro, vec3 rd, real t, vec3 up,
                       real density, real falloff, real base)
{
    real h0 = v3_dot(ro, up) - base;
    real k = falloff * v3_dot(rd, up);
    real kt = k * t;
    real safe_k = SEL(k, (real)(1.0f), fabs(kt) < 1e-4f);
    real path = SEL((1.0f - exp(-kt)) / safe_k, t * (1.0f - 0.5f * kt), fabs(kt) < 1e-4f);
    real depth = density * exp(fmin(-falloff * h0, K(60.0f))) * path;
    return v3_mix(fog_color, c, exp(-fmax(depth, K(0.0f))));
}

//! fn fresnel_schlick
//! class: helper
// Schlick's approximation of the Fresnel reflectance (seed 000 Listing 6);
// r0 is the reflectance at normal incidence, cos_v the cosine to the viewer.
inline real fresnel_schlick(real r0, real cos_v)
{
    real m = 1.0f - clamp(cos_v, K(0.0f), K(1.0f));
    real m2 = m * m;
    return r0 + (1.0f - r0) * m2 * m2 * m;
}

//! fn tonemap_reinhard
//! deps: vec3_ops
//! class: helper
// Reinhard's curve c / (1 + c) per channel.
inline vec3 tonemap_reinhard(vec3 c)
{
    return v3(c.x / (1.0f + c.x), c.y / (1.0f + c.y), c.z / (1.0f + c.z));
}

//! fn tonemap_aces
//! deps: vec3_ops
//! class: helper
// Narkowicz's fit of the ACES filmic curve, per channel, with his 0.6
// pre-scale so that mid-grey stays near mid-grey.
inline real tonemap_aces_1(real x)
{
    x = 0.6f * fmax(x, K(0.0f));
    return clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), K(0.0f), K(1.0f));
}
inline vec3 tonemap_aces(vec3 c) { return v3(tonemap_aces_1(c.x), tonemap_aces_1(c.y), tonemap_aces_1(c.z)); }
