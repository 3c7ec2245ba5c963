// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.09795524f)), v3(6.0f, 6.0f, 1.2020447f), 0.0f);  // bounding box  (mandelbulb.yaml:12)
    real d1 = b0;
    if (M_ANY(b0 <= 1.5f))
    {
        vec3 p2 = v3_sub(p, v3(0.0f, 0.0f, -1.25f));  // translate x=0 y=0 z=-1.25  (mandelbulb.yaml:16)
        real d3 = sd_box(p2, v3(6.0f, 6.0f, 0.05f), 0.0f);  // box hx=6 hy=6 hz=0.05 radius=0  (mandelbulb.yaml:15)
        real b4 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.1040895f, 1.1040895f, 1.1040895f), 0.0f);  // bounding box  (mandelbulb.yaml:14)
        real d5 = b4;
        if (M_ANY(b4 <= 0.27602237f))
        {
            real d6 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (mandelbulb.yaml:13)
            d5 = SEL(d6, b4, b4 > 0.27602237f);
        }
        real d7 = d3;  // union  (mandelbulb.yaml:12)
        d7 = fmin(d7, d5);
        d1 = SEL(d7, b0, b0 > 1.5f);
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
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.09795524f)), v3(6.0f, 6.0f, 1.2020447f), 0.0f);  // bounding box  (mandelbulb.yaml:12)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 1.5f))
    {
        vec3 p3 = v3_sub(p, v3(0.0f, 0.0f, -1.25f));  // translate x=0 y=0 z=-1.25  (mandelbulb.yaml:16)
        real d4 = sd_box(p3, v3(6.0f, 6.0f, 0.05f), 0.0f);  // box hx=6 hy=6 hz=0.05 radius=0  (mandelbulb.yaml:15)
        real b5 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.1040895f, 1.1040895f, 1.1040895f), 0.0f);  // bounding box  (mandelbulb.yaml:14)
        real d6 = b5;
        real m7 = (real)(0.0f);
        if (M_ANY(b5 <= 0.27602237f))
        {
            real d8 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (mandelbulb.yaml:13)
            d6 = SEL(d8, b5, b5 > 0.27602237f);
            m7 = SEL((real)(1.0f), (real)(0.0f), b5 > 0.27602237f);
        }
        real d9 = d4;  // union  (mandelbulb.yaml:12)
        real m10 = (real)(2.0f);
        m10 = SEL(m10, m7, d6 < d9);
        d9 = fmin(d9, d6);
        d1 = SEL(d9, b0, b0 > 1.5f);
        m2 = SEL(m10, (real)(0.0f), b0 > 1.5f);
    }
    *mat = m2;
    return d1;
}

// ---- orbit trap of the nearest fractal: evaluated once per hit, for orbit-trap materials ----
real scene_trap(TIME_PARAM vec3 p)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.09795524f)), v3(6.0f, 6.0f, 1.2020447f), 0.0f);  // bounding box  (mandelbulb.yaml:12)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 1.5f))
    {
        vec3 p3 = v3_sub(p, v3(0.0f, 0.0f, -1.25f));  // translate x=0 y=0 z=-1.25  (mandelbulb.yaml:16)
        real d4 = sd_box(p3, v3(6.0f, 6.0f, 0.05f), 0.0f);  // box hx=6 hy=6 hz=0.05 radius=0  (mandelbulb.yaml:15)
        real b5 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.1040895f, 1.1040895f, 1.1040895f), 0.0f);  // bounding box  (mandelbulb.yaml:14)
        real d6 = b5;
        real m7 = (real)(0.0f);
        if (M_ANY(b5 <= 0.27602237f))
        {
            real d8 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (mandelbulb.yaml:13)
            real oiter10;
            real ocount11;
            real otrap9 = trap_mandelbulb_int(p, 8, 10, 2.0f, 0, v3_splat(0.0f), &oiter10, &ocount11);
            real trap12 = otrap9;  // orbit trap
            d6 = SEL(d8, b5, b5 > 0.27602237f);
            m7 = SEL(trap12, (real)(0.0f), b5 > 0.27602237f);
        }
        real d13 = d4;  // union  (mandelbulb.yaml:12)
        real m14 = (real)(0.0f);
        m14 = SEL(m14, m7, d6 < d13);
        d13 = fmin(d13, d6);
        d1 = SEL(d13, b0, b0 > 1.5f);
        m2 = SEL(m14, (real)(0.0f), b0 > 1.5f);
    }
    (void)d1;
    return m2;
}

// ---- the scene's exact gradient (render.normals: dual), evaluated once per hit ----
vec3 scene_normal_dual(vec3 p)
{
    vec3 p0 = v3_sub(p, v3(0.0f, 0.0f, -1.25f));
    vec3 g2;
    real d1 = sdg_box(p0, v3(6.0f, 6.0f, 0.05f), 0.0f, &g2);  // box
    real d3 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb
    vec3 g4 = deg_mandelbulb(p, 8.0f, 10, 2.0f, 0, v3_splat(0.0f));  // the normal's direction
    real d5 = d1;  // union
    vec3 g6 = g2;
    g6 = v3_select(g6, g4, d3 < d5);
    d5 = fmin(d5, d3);
    (void)d5;
    return v3_normalize(g6);
}

