// ---- scene distance: the march evaluates this at every step ----
real scene_dist(TIME_PARAM vec3 p)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.12295524f)), v3(2.0f, 2.0f, 1.2270447f), 0.0f);  // bounding box  (mandelbulb.yaml:12)
    real d1 = b0;
    if (M_ANY(b0 <= 0.5f))
    {
        real b2 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.1040895f, 1.1040895f, 1.1040895f), 0.0f);  // bounding box  (mandelbulb.yaml:14)
        real d3 = b2;
        if (M_ANY(b2 <= 0.27602237f))
        {
            real d4 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (mandelbulb.yaml:13)
            d3 = SEL(d4, b2, b2 > 0.27602237f);
        }
        vec3 p5 = v3_sub(p, v3(0.0f, 0.0f, -1.3f));  // translate x=0 y=0 z=-1.3  (mandelbulb.yaml:16)
        real d6 = sd_box(p5, v3(2.0f, 2.0f, 0.05f), 0.0f);  // box hx=2 hy=2 hz=0.05 radius=0  (mandelbulb.yaml:15)
        real d7 = d3;  // union  (mandelbulb.yaml:12)
        d7 = fmin(d7, d6);
        d1 = SEL(d7, b0, b0 > 0.5f);
    }
    return d1;
}

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.12295524f)), v3(2.0f, 2.0f, 1.2270447f), 0.0f);  // bounding box  (mandelbulb.yaml:12)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 0.5f))
    {
        real b3 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.1040895f, 1.1040895f, 1.1040895f), 0.0f);  // bounding box  (mandelbulb.yaml:14)
        real d4 = b3;
        real m5 = (real)(0.0f);
        if (M_ANY(b3 <= 0.27602237f))
        {
            real d6 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (mandelbulb.yaml:13)
            d4 = SEL(d6, b3, b3 > 0.27602237f);
            m5 = SEL((real)(1.0f), (real)(0.0f), b3 > 0.27602237f);
        }
        vec3 p7 = v3_sub(p, v3(0.0f, 0.0f, -1.3f));  // translate x=0 y=0 z=-1.3  (mandelbulb.yaml:16)
        real d8 = sd_box(p7, v3(2.0f, 2.0f, 0.05f), 0.0f);  // box hx=2 hy=2 hz=0.05 radius=0  (mandelbulb.yaml:15)
        real d9 = d4;  // union  (mandelbulb.yaml:12)
        real m10 = m5;
        m10 = SEL(m10, (real)(0.0f), d8 < d9);
        d9 = fmin(d9, d8);
        d1 = SEL(d9, b0, b0 > 0.5f);
        m2 = SEL(m10, (real)(0.0f), b0 > 0.5f);
    }
    *mat = m2;
    return d1;
}

// ---- the scene's exact gradient (render.normals: dual), evaluated once per hit ----
vec3 scene_normal_dual(vec3 p)
{
    real d0 = de_mandelbulb_int(p, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb
    vec3 g1 = gn_mandelbulb(p, 8.0f, 10, 2.0f, 0, v3_splat(0.0f));  // the direction of grad |z_n|
    vec3 p2 = v3_sub(p, v3(0.0f, 0.0f, -1.3f));
    vec3 g4;
    real d3 = sdg_box(p2, v3(2.0f, 2.0f, 0.05f), 0.0f, &g4);  // box
    real d5 = d0;  // union
    vec3 g6 = g1;
    g6 = v3_select(g6, g4, d3 < d5);
    d5 = fmin(d5, d3);
    (void)d5;
    return v3_normalize(g6);
}

