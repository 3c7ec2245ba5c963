// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(2.5625f, 2.5625f, 2.3125f), 0.0f);  // bounding box  (hybrid.yaml:25)
    real d1 = b0;
    if (M_ANY(b0 <= 0.640625f))
    {
        real hyb2;  // hybrid orbit: 12 iterations, the step pattern repeats every 3
        {
            vec3 z = p;
            real dr = 1.0f;
            real r = v3_length(z);
            mask alive = r < 100.0f;  // the escape radius, not the bailout: see ir::hybrid_escape_radius
            for (int i = 0; i < 12 && M_ANY(alive); ++i) {
                const int k = i % 3;  // the same step for every lane
                real dr_next = dr;
                vec3 z_next;
                if (k < 1) z_next = fold_hybrid_bulb_int(z, 8, p, &dr_next);  // mandelbulb power 8
                else z_next = fold_hybrid_box(z, 2.0f, 0.25f, 1.0f, 1.0f, p, &dr_next);  // mandelbox scale 2
                z = v3_select(z, z_next, alive);
                dr = SEL(dr, dr_next, alive);
                r = v3_length(z);
                alive = alive & (r < 100.0f);
            }
            hyb2 = r / fabs(dr);  // the linear estimator: below the log one at the escape radius
            // far field: the set lies inside the bailout ball, so beyond twice its radius the distance to
            // the ball is a true bound and a longer step
            real r0 = v3_length(p);
            hyb2 = SEL(hyb2, r0 - 4.0f, r0 > 8.0f);
        }
        real d3 = hyb2;  // hybrid iterations=12 bailout=4 steps=2 k0=0 n0=1 a0=8 b0=0 c0=0 d0=0 k1=1 n1=2 a1=2 b1=0.5 c1=1 d1=1 k2=0 n2=0 a2=0 b2=0 c2=0 d2=0 k3=0 n3=0 a3=0 b3=0 c3=0 d3=0  (hybrid.yaml:18)
        d1 = SEL(d3, b0, b0 > 0.640625f);
    }
    (void)live;
    return d1;
}

// ---- scene distance, called: every use outside the marching loops ----
__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }
inline real scene_dist_probe(TIME_PARAM vec3 p, real below, mask live) { (void)below; (void)live; return scene_dist(TIME_ARG p); }

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(2.5625f, 2.5625f, 2.3125f), 0.0f);  // bounding box  (hybrid.yaml:25)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 0.640625f))
    {
        real hyb3;  // hybrid orbit: 12 iterations, the step pattern repeats every 3
        {
            vec3 z = p;
            real dr = 1.0f;
            real r = v3_length(z);
            mask alive = r < 100.0f;  // the escape radius, not the bailout: see ir::hybrid_escape_radius
            for (int i = 0; i < 12 && M_ANY(alive); ++i) {
                const int k = i % 3;  // the same step for every lane
                real dr_next = dr;
                vec3 z_next;
                if (k < 1) z_next = fold_hybrid_bulb_int(z, 8, p, &dr_next);  // mandelbulb power 8
                else z_next = fold_hybrid_box(z, 2.0f, 0.25f, 1.0f, 1.0f, p, &dr_next);  // mandelbox scale 2
                z = v3_select(z, z_next, alive);
                dr = SEL(dr, dr_next, alive);
                r = v3_length(z);
                alive = alive & (r < 100.0f);
            }
            hyb3 = r / fabs(dr);  // the linear estimator: below the log one at the escape radius
            // far field: the set lies inside the bailout ball, so beyond twice its radius the distance to
            // the ball is a true bound and a longer step
            real r0 = v3_length(p);
            hyb3 = SEL(hyb3, r0 - 4.0f, r0 > 8.0f);
        }
        real d4 = hyb3;  // hybrid iterations=12 bailout=4 steps=2 k0=0 n0=1 a0=8 b0=0 c0=0 d0=0 k1=1 n1=2 a1=2 b1=0.5 c1=1 d1=1 k2=0 n2=0 a2=0 b2=0 c2=0 d2=0 k3=0 n3=0 a3=0 b3=0 c3=0 d3=0  (hybrid.yaml:18)
        d1 = SEL(d4, b0, b0 > 0.640625f);
        m2 = SEL((real)(1.0f), (real)(0.0f), b0 > 0.640625f);
    }
    *mat = m2;
    return d1;
}

// ---- orbit trap of the nearest fractal: evaluated once per hit, for orbit-trap materials ----
real scene_trap(TIME_PARAM vec3 p)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(2.5625f, 2.5625f, 2.3125f), 0.0f);  // bounding box  (hybrid.yaml:25)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 0.640625f))
    {
        real hyb3;  // hybrid orbit: 12 iterations, the step pattern repeats every 3
        {
            vec3 z = p;
            real dr = 1.0f;
            real r = v3_length(z);
            mask alive = r < 100.0f;  // the escape radius, not the bailout: see ir::hybrid_escape_radius
            for (int i = 0; i < 12 && M_ANY(alive); ++i) {
                const int k = i % 3;  // the same step for every lane
                real dr_next = dr;
                vec3 z_next;
                if (k < 1) z_next = fold_hybrid_bulb_int(z, 8, p, &dr_next);  // mandelbulb power 8
                else z_next = fold_hybrid_box(z, 2.0f, 0.25f, 1.0f, 1.0f, p, &dr_next);  // mandelbox scale 2
                z = v3_select(z, z_next, alive);
                dr = SEL(dr, dr_next, alive);
                r = v3_length(z);
                alive = alive & (r < 100.0f);
            }
            hyb3 = r / fabs(dr);  // the linear estimator: below the log one at the escape radius
            // far field: the set lies inside the bailout ball, so beyond twice its radius the distance to
            // the ball is a true bound and a longer step
            real r0 = v3_length(p);
            hyb3 = SEL(hyb3, r0 - 4.0f, r0 > 8.0f);
        }
        real d4 = hyb3;  // hybrid iterations=12 bailout=4 steps=2 k0=0 n0=1 a0=8 b0=0 c0=0 d0=0 k1=1 n1=2 a1=2 b1=0.5 c1=1 d1=1 k2=0 n2=0 a2=0 b2=0 c2=0 d2=0 k3=0 n3=0 a3=0 b3=0 c3=0 d3=0  (hybrid.yaml:18)
        real htrap5;  // hybrid orbit trap
        {
            vec3 z = p;
            real dr = 1.0f, trap = 1e10f, n = 0.0f, growth = 2.0f, power_law = 0.0f;
            real r = v3_length(z);
            mask alive = r < 100.0f;
            for (int i = 0; i < 12 && M_ANY(alive); ++i) {
                const int k = i % 3;
                vec3 z_next;
                real g, law;
                if (k < 1) { z_next = fold_hybrid_bulb_int(z, 8, p, &dr); g = 8.0f; law = 1.0f; }
                else { z_next = fold_hybrid_box(z, 2.0f, 0.25f, 1.0f, 1.0f, p, &dr); g = 2.0f; law = 0.0f; }
                z = v3_select(z, z_next, alive);
                n = SEL(n, n + 1.0f, alive);
                growth = SEL(growth, (real)(g), alive);
                power_law = SEL(power_law, (real)(law), alive);
                trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
                r = v3_length(z);
                alive = alive & (r < 100.0f);
            }
            htrap5 = trap;
        }
        real trap6 = htrap5;  // orbit trap
        d1 = SEL(d4, b0, b0 > 0.640625f);
        m2 = SEL(trap6, (real)(0.0f), b0 > 0.640625f);
    }
    (void)d1;
    return m2;
}

