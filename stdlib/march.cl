//! fn ray_box
//! deps: vec3_ops
//! class: helper
// Slab test: the interval [t0, t1] of the ray inside the box [lo, hi].
// Returns the lanes whose ray meets the box in front of the camera.
inline mask ray_box(vec3 ro, vec3 rd, vec3 lo, vec3 hi, real* t0, real* t1)
{
    // 1/rd with the sign kept for zero components, so slabs stay ordered.
    vec3 inv = v3(1.0f / SEL(rd.x, copysign(K(1e-30f), rd.x), fabs(rd.x) < 1e-30f),
                  1.0f / SEL(rd.y, copysign(K(1e-30f), rd.y), fabs(rd.y) < 1e-30f),
                  1.0f / SEL(rd.z, copysign(K(1e-30f), rd.z), fabs(rd.z) < 1e-30f));
    vec3 a = v3_mul(v3_sub(lo, ro), inv), b = v3_mul(v3_sub(hi, ro), inv);
    real tn = fmax(fmax(fmin(a.x, b.x), fmin(a.y, b.y)), fmin(a.z, b.z));
    real tf = fmin(fmin(fmax(a.x, b.x), fmax(a.y, b.y)), fmax(a.z, b.z));
    *t0 = fmax(tn, K(0.0f));
    *t1 = tf;
    return (tf >= tn) & (tf > 0.0f);
}

//! fn march_advance
//! class: helper
// One step of a sphere trace, shared by the marching loops: a lane whose
// distance d is under the hit band at t (hit_eps pixels) stops with a hit;
// the others step by d times step_factor and stop past t1. `n` counts each
// lane's steps.
inline void march_advance(real d, real t1, real pixel_angle, real hit_eps, real step_factor, real* t, mask* active,
                          mask* hit, real* n)
{
    mask now_hit = *active & (d < hit_eps * pixel_angle * fmax(*t, K(1e-4f)));
    *hit = *hit | now_hit;
    *active = *active & !now_hit;
    *n = SEL(*n, *n + 1.0f, *active | now_hit);
    *t = SEL(*t, *t + d * step_factor, *active);
    *active = *active & (*t < t1);
}

//! fn march_sphere_trace
//! deps: vec3_ops, march_advance
//! after-scene
//! class: helper
// Sphere tracing from t0 to t1. A lane hits when the distance drops below
// hit_eps times the pixel footprint at t (t * pixel_angle), so precision
// follows the pixel size instead of a fixed epsilon. Lanes that run out of
// steps count as misses. `*steps` returns the steps each lane took.
inline mask march_sphere_trace(TIME_PARAM vec3 ro, vec3 rd, real t0, real t1, mask active,
                               real pixel_angle, real hit_eps, real step_factor,
                               int max_steps, real* t_out, real* steps)
{
    real t = t0;
    mask hit = active & !active;
    real n = 0.0f;
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = scene_dist_inline(TIME_ARG v3_mad(ro, rd, t), active);
        march_advance(d, t1, pixel_angle, hit_eps, step_factor, &t, &active, &hit, &n);
    }
    *t_out = t;
    *steps = n;
    return hit;
}

//! fn normal_tetrahedral
//! deps: vec3_ops
//! after-scene
//! class: helper
// Four-tap tetrahedral gradient (seed 000 Eq. 5): the cheapest symmetric
// finite difference. h follows the pixel footprint at the hit.
inline vec3 normal_tetrahedral(TIME_PARAM vec3 p, real h)
{
    real a = scene_dist(TIME_ARG v3(p.x + h, p.y - h, p.z - h));
    real b = scene_dist(TIME_ARG v3(p.x - h, p.y - h, p.z + h));
    real c = scene_dist(TIME_ARG v3(p.x - h, p.y + h, p.z - h));
    real d = scene_dist(TIME_ARG v3(p.x + h, p.y + h, p.z + h));
    return v3_normalize(v3(a - b - c + d, -a - b + c + d, -a + b - c + d));
}

//! fn normal_central
//! deps: vec3_ops
//! after-scene
//! class: helper
// Six-tap central differences.
inline vec3 normal_central(TIME_PARAM vec3 p, real h)
{
    real dx = scene_dist(TIME_ARG v3(p.x + h, p.y, p.z)) - scene_dist(TIME_ARG v3(p.x - h, p.y, p.z));
    real dy = scene_dist(TIME_ARG v3(p.x, p.y + h, p.z)) - scene_dist(TIME_ARG v3(p.x, p.y - h, p.z));
    real dz = scene_dist(TIME_ARG v3(p.x, p.y, p.z + h)) - scene_dist(TIME_ARG v3(p.x, p.y, p.z - h));
    return v3_normalize(v3(dx, dy, dz));
}

//! fn normal_tap_bound
//! deps: vec3_ops
//! class: helper
// Where the scene's distance is 1-Lipschitz and is d at p, a normal's tap
// `reach` away from p is at most d + reach (plus rounding's slack): the
// bound scene_dist_below lets an object set's walk cull by, so it skips
// every box farther than that. The taps' values are the same, found in
// fewer boxes (see bounded_normals in the compiler).
inline real normal_tap_bound(vec3 p, real d, real reach)
{
    return d + reach * K(1.001f) + K(1e-5f) * (K(1.0f) + v3_max_comp(v3_abs(p)));
}

//! fn normal_tetrahedral_below
//! deps: vec3_ops, normal_tap_bound, os_cone
//! after-scene
//! class: helper
// normal_tetrahedral with its taps (sqrt(3) h away) bounded by normal_tap_bound.
// Only the `live` lanes' normals are used (the hits); `cone` is the packet's
// (os_cone_shading), whose list answers most taps, or none.
inline vec3 normal_tetrahedral_below(TIME_PARAM vec3 p, real h, real d, mask live, const os_cone cone)
{
    const real ub = normal_tap_bound(p, d, K(1.7320508f) * h);
    real a = scene_dist_below(TIME_ARG v3(p.x + h, p.y - h, p.z - h), ub, live, cone);
    real b = scene_dist_below(TIME_ARG v3(p.x - h, p.y - h, p.z + h), ub, live, cone);
    real c = scene_dist_below(TIME_ARG v3(p.x - h, p.y + h, p.z - h), ub, live, cone);
    real e = scene_dist_below(TIME_ARG v3(p.x + h, p.y + h, p.z + h), ub, live, cone);
    return v3_normalize(v3(a - b - c + e, -a - b + c + e, -a + b - c + e));
}

//! fn normal_central_below
//! deps: vec3_ops, normal_tap_bound, os_cone
//! after-scene
//! class: helper
// normal_central with its taps (h away) bounded by normal_tap_bound; `live`
// and `cone` as for normal_tetrahedral_below.
inline vec3 normal_central_below(TIME_PARAM vec3 p, real h, real d, mask live, const os_cone cone)
{
    const real ub = normal_tap_bound(p, d, h);
    real dx = scene_dist_below(TIME_ARG v3(p.x + h, p.y, p.z), ub, live, cone)
              - scene_dist_below(TIME_ARG v3(p.x - h, p.y, p.z), ub, live, cone);
    real dy = scene_dist_below(TIME_ARG v3(p.x, p.y + h, p.z), ub, live, cone)
              - scene_dist_below(TIME_ARG v3(p.x, p.y - h, p.z), ub, live, cone);
    real dz = scene_dist_below(TIME_ARG v3(p.x, p.y, p.z + h), ub, live, cone)
              - scene_dist_below(TIME_ARG v3(p.x, p.y, p.z - h), ub, live, cone);
    return v3_normalize(v3(dx, dy, dz));
}

//! fn ray_box_exit
//! deps: vec3_ops, ray_box
//! class: helper
// Where a ray from inside (or near) the box [lo, hi] leaves it, capped at
// tmax; 0 when the ray misses the box, so a shadow ray stops where nothing
// can block it any more.
inline real ray_box_exit(vec3 ro, vec3 rd, vec3 lo, vec3 hi, real tmax)
{
    real t0, t1;
    mask meets = ray_box(ro, rd, lo, hi, &t0, &t1);
    return SEL((real)(0.0f), fmin(t1, tmax), meets);
}

//! fn ray_sphere
//! deps: vec3_ops
//! class: helper
// The interval [t0, t1] of a ray (unit direction) inside the ball of radius
// r around c. Returns the lanes whose ray meets the ball in front of the origin.
inline mask ray_sphere(vec3 ro, vec3 rd, vec3 c, real r, real* t0, real* t1)
{
    vec3 oc = v3_sub(ro, c);
    real b = v3_dot(oc, rd);
    real disc = b * b - (v3_dot(oc, oc) - r * r);
    real s = sqrt(fmax(disc, K(0.0f)));
    *t0 = fmax(-b - s, K(0.0f));
    *t1 = -b + s;
    return (disc >= 0.0f) & (*t1 > 0.0f);
}

//! fn ray_sphere_exit
//! deps: vec3_ops, ray_sphere
//! class: helper
// Where a ray from inside (or near) the ball leaves it, capped at tmax; 0
// when the ray misses the ball.
inline real ray_sphere_exit(vec3 ro, vec3 rd, vec3 c, real r, real tmax)
{
    real t0, t1;
    mask meets = ray_sphere(ro, rd, c, r, &t0, &t1);
    return SEL((real)(0.0f), fmin(t1, tmax), meets);
}

//! fn march_sphere_trace_refined
//! deps: vec3_ops
//! after-scene
//! class: helper
// The reference march (render.refine: bisection): march_sphere_trace that
// remembers the last point outside, then brackets the surface and bisects
// it. The bracket is [last point outside, hit] when the hit landed inside
// (d < 0, an overshoot), or [hit, hit + 2 eps] when a point that close
// ahead is inside; a lane without a sign change keeps its hit, which is
// within hit_eps pixels already. Also returns the closest approach (glow).
inline mask march_sphere_trace_refined(TIME_PARAM vec3 ro, vec3 rd, real t0, real t1, mask active,
                                       real pixel_angle, real hit_eps, real step_factor,
                                       int max_steps, real* t_out, real* steps, real* closest)
{
    real t = t0, t_prev = t0, d_hit = 0.0f;
    mask hit = active & !active;
    real n = 0.0f;
    real c = (real)(1e30f);
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = scene_dist_inline(TIME_ARG v3_mad(ro, rd, t), active);
        c = SEL(c, fmin(c, d), active);
        mask now_hit = active & (d < hit_eps * pixel_angle * fmax(t, K(1e-4f)));
        d_hit = SEL(d_hit, d, now_hit);
        hit = hit | now_hit;
        active = active & !now_hit;
        n = SEL(n, n + 1.0f, active | now_hit);
        t_prev = SEL(t_prev, t, active);
        t = SEL(t, t + d * step_factor, active);
        active = active & (t < t1);
    }
    real eps = hit_eps * pixel_angle * fmax(t, K(1e-4f));
    real ahead = t + 2.0f * eps;
    mask inside_ahead = hit & (d_hit >= 0.0f) & (scene_dist(TIME_ARG v3_mad(ro, rd, ahead)) < 0.0f);
    mask bracketed = (hit & (d_hit < 0.0f)) | inside_ahead;
    real lo = SEL(t_prev, t, inside_ahead), hi = SEL(t, ahead, inside_ahead);
    for (int i = 0; i < 60 && M_ANY(bracketed); ++i) {
        real mid = 0.5f * (lo + hi);
        mask in = scene_dist(TIME_ARG v3_mad(ro, rd, mid)) < 0.0f;
        hi = SEL(hi, mid, bracketed & in);
        lo = SEL(lo, mid, bracketed & !in);
    }
    // the outside end of the bracket: shading and normals see the surface from outside
    *t_out = SEL(t, lo, bracketed);
    *steps = n;
    *closest = c;
    return hit;
}
