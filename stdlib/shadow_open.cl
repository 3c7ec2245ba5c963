//! fn shadow_soft_open
//! deps: vec3_ops
//! after-scene
//! class: estimate
// shadow_soft for a scene of bounded parts inside the box [lo, hi] standing
// on planes (a fractal on a floor): the same steps and the same result, but a
// lane stops as soon as no later step can lower its penumbra minimum, where
// shadow_soft would march on to tmax. Outside the box the scene's distance
// is at least the box's, f (the planes are left out by `climbs`: the lanes
// whose ray rises from every plane at a slope of at least 1/k, so k d / t
// stays >= 1 on them). f is convex along the ray, so once f grows at least
// as fast as f / t (dot(off, l) t >= f^2, off the offset from the box) it
// keeps doing so, k f / t never falls again, and k f >= res t settles res.
// A separate function so scenes without such planes keep the plain loop.
inline real shadow_soft_open(TIME_PARAM vec3 p, vec3 l, real tmin, real tmax, real k, real eps, real min_step,
                             int max_steps, mask active, vec3 lo, vec3 hi, mask climbs)
{
    real res = 1.0f;
    real t = tmin;
    const real inv_k1 = 1.0f / (k + 1.0f);  // for the whole steps, as in shadow_soft
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        vec3 q = v3_mad(p, l, t);
        real d = scene_dist_inline(TIME_ARG q, active);
        res = SEL(res, fmin(res, k * d / t), active);
        res = SEL(res, (real)(0.0f), active & (d < eps));
        active = active & (d >= eps) & (res > 0.002f);
        vec3 off = v3(q.x - clamp(q.x, lo.x, hi.x), q.y - clamp(q.y, lo.y, hi.y), q.z - clamp(q.z, lo.z, hi.z));
        real f2 = v3_dot(off, off);
        active = active & !(climbs & (f2 > 0.0f) & (v3_dot(off, l) * t >= f2) & (k * sqrt(f2) >= res * t));
        real cap = fmax(0.25f * t, 4.0f * min_step);
        real skip = (k * d - res * t) * inv_k1;
        t = SEL(t, t + clamp(d, min_step, fmax(cap, skip)), active);
        active = active & (t < tmax);
    }
    return clamp(res, K(0.0f), K(1.0f));
}
