//! fn march_signed
//! deps: vec3_ops, march_advance
//! after-scene
//! class: helper
// Sphere tracing as march_sphere_trace, on side * scene_dist: side 1 marches
// outside the surfaces, side -1 inside a solid (a path inside glass), where
// the negated distance is the distance to the surface from within.
// A copy rather than a change to march_sphere_trace, so kernels without
// glass stay as they were.
inline mask march_signed(TIME_PARAM vec3 ro, vec3 rd, real side, real t0, real t1, mask active,
                         real pixel_angle, real hit_eps, real step_factor,
                         int max_steps, real* t_out, real* steps)
{
    real t = t0;
    mask hit = active & !active;
    real n = 0.0f;
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = side * scene_dist_inline(TIME_ARG v3_mad(ro, rd, t), active);
        march_advance(d, t1, pixel_angle, hit_eps, step_factor, &t, &active, &hit, &n);
    }
    *t_out = t;
    *steps = n;
    return hit;
}

//! fn glass_fresnel
//! class: exact
// The exact Fresnel reflectance of a smooth dielectric for unpolarised
// light: ci, ct the cosines of the incident and transmitted angles, eta the
// ratio of the indices (incident over transmitted). The caller handles
// total internal reflection (no ct).
inline real glass_fresnel(real ci, real ct, real eta)
{
    real rs = (eta * ci - ct) / fmax(eta * ci + ct, K(1e-12f));
    real rp = (ci - eta * ct) / fmax(ci + eta * ct, K(1e-12f));
    return 0.5f * (rs * rs + rp * rp);
}

//! fn glass_absorb
//! deps: vec3_ops
//! class: exact
// Beer-Lambert: the share of light left after `len` through a medium that
// absorbs sigma per unit length.
inline vec3 glass_absorb(vec3 sigma, real len)
{
    return v3(exp(-sigma.x * len), exp(-sigma.y * len), exp(-sigma.z * len));
}
