// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.34625f, 0.12691228f)), v3(4.5f, 3.15375f, 1.3959504f), 0.0f);  // bounding box  (fractal-zoo.yaml:18)
    real d1 = b0;
    if (M_ANY(b0 <= 1.125f))
    {
        real b2 = sd_box(v3_sub(p, v3(2.6f, 0.6f, 0.03f)), v3(1.1830126f, 1.1830126f, 1.299038f), 0.0f);  // bounding box  (fractal-zoo.yaml:38)
        real d3 = b2;
        if (M_ANY(b2 <= 0.3247595f))
        {
            vec3 p4 = v3_sub(p, v3(2.6f, 0.6f, 0.03f));  // translate x=2.6 y=0.6 z=0.03  (fractal-zoo.yaml:41)
            vec3 p5 = v3_mat(p4, 0.7886752f, -0.2113248f, -0.5773502f, -0.2113248f, 0.7886752f, -0.5773502f, 0.5773502f, 0.5773502f, 0.57735044f);  // rotate  (fractal-zoo.yaml:39)
            vec3 p6 = v3_scale(p5, 1.3333334f);  // scale s=0.75  (fractal-zoo.yaml:40)
            real d7 = de_sierpinski(p6, 8, 2.0f);  // sierpinski iterations=8 scale=2  (fractal-zoo.yaml:37)
            real d8 = d7 * 0.75f;  // undo the scale on the distance
            d3 = SEL(d8, b2, b2 > 0.3247595f);
        }
        real b9 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.75f)), v3(0.7728627f, 0.7728627f, 0.7728627f), 0.0f);  // bounding box  (fractal-zoo.yaml:21)
        real d10 = b9;
        if (M_ANY(b9 <= 0.19321567f))
        {
            vec3 p11 = v3_sub(p, v3(0.0f, 0.0f, 0.75f));  // translate x=0 y=0 z=0.75  (fractal-zoo.yaml:22)
            vec3 p12 = v3_scale(p11, 1.4285715f);  // scale s=0.7  (fractal-zoo.yaml:23)
            real d13 = de_mandelbulb_int(p12, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (fractal-zoo.yaml:20)
            real d14 = d13 * 0.7f;  // undo the scale on the distance
            d10 = SEL(d14, b9, b9 > 0.19321567f);
        }
        vec3 p15 = v3_sub(p, v3(0.0f, -2.2f, 0.12f));  // translate x=0 y=-2.2 z=0.12  (fractal-zoo.yaml:49)
        real d16 = sd_torus(p15, 0.45f, 0.12f);  // torus major=0.45 minor=0.12  (fractal-zoo.yaml:46)
        real d17 = sd_capsule(p15, v3(0.0f, 0.0f, -0.3f), v3(0.0f, 0.0f, 0.5f), 0.1f);  // capsule ax=0 ay=0 az=-0.3 bx=0 by=0 bz=0.5 radius=0.1  (fractal-zoo.yaml:47)
        real d18 = d16;  // smooth_union radius=0.15  (fractal-zoo.yaml:43)
        d18 = op_blend_polynomial(d18, d17, 0.15f);
        vec3 p19 = v3_sub(p, v3(0.0f, 0.5f, -0.45f));  // translate x=0 y=0.5 z=-0.45  (fractal-zoo.yaml:53)
        real d20 = sd_box(p19, v3(4.5f, 3.0f, 0.05f), 0.0f);  // box hx=4.5 hy=3 hz=0.05 radius=0  (fractal-zoo.yaml:51)
        vec3 p21 = v3_sub(p, v3(0.0f, 0.0f, -0.2f));  // translate x=0 y=0 z=-0.2  (fractal-zoo.yaml:26)
        real d22 = sd_cylinder(p21, 0.55f, 0.2f);  // cylinder radius=0.55 half_height=0.2  (fractal-zoo.yaml:24)
        real b23 = sd_box(v3_sub(p, v3(-2.6f, 0.6f, 0.2f)), v3(0.79735565f, 0.79735565f, 0.6f), 0.0f);  // bounding box  (fractal-zoo.yaml:32)
        real d24 = b23;
        if (M_ANY(b23 <= 0.19933891f))
        {
            vec3 p25 = v3_sub(p, v3(-2.6f, 0.6f, 0.2f));  // translate x=-2.6 y=0.6 z=0.2  (fractal-zoo.yaml:35)
            vec3 p26 = v3_mat(p25, 0.9063078f, 0.42261827f, 0.0f, -0.42261827f, 0.9063078f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (fractal-zoo.yaml:34)
            vec3 p27 = v3_scale(p26, 1.6666666f);  // scale s=0.6  (fractal-zoo.yaml:33)
            real d28 = de_menger(p27, 4, 3.0f);  // menger iterations=4 scale=3  (fractal-zoo.yaml:29)
            vec3 p29 = v3_sub(p27, v3(0.7f, -0.7f, 0.7f));  // translate x=0.7 y=-0.7 z=0.7  (fractal-zoo.yaml:31)
            real d30 = sd_sphere(p29, 0.7f);  // sphere radius=0.7  (fractal-zoo.yaml:30)
            real d31 = d28;  // difference  (fractal-zoo.yaml:28)
            d31 = fmax(d31, -d30);
            real d32 = d31 * 0.6f;  // undo the scale on the distance
            d24 = SEL(d32, b23, b23 > 0.19933891f);
        }
        real d33 = d3;  // union  (fractal-zoo.yaml:18)
        d33 = fmin(d33, d10);
        d33 = fmin(d33, d18);
        d33 = fmin(d33, d20);
        d33 = fmin(d33, d22);
        d33 = fmin(d33, d24);
        d1 = SEL(d33, b0, b0 > 1.125f);
    }
    (void)live;
    return d1;
}

// ---- scene distance, called: every use outside the marching loops ----
__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.34625f, 0.12691228f)), v3(4.5f, 3.15375f, 1.3959504f), 0.0f);  // bounding box  (fractal-zoo.yaml:18)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 1.125f))
    {
        real b3 = sd_box(v3_sub(p, v3(2.6f, 0.6f, 0.03f)), v3(1.1830126f, 1.1830126f, 1.299038f), 0.0f);  // bounding box  (fractal-zoo.yaml:38)
        real d4 = b3;
        real m5 = (real)(0.0f);
        if (M_ANY(b3 <= 0.3247595f))
        {
            vec3 p6 = v3_sub(p, v3(2.6f, 0.6f, 0.03f));  // translate x=2.6 y=0.6 z=0.03  (fractal-zoo.yaml:41)
            vec3 p7 = v3_mat(p6, 0.7886752f, -0.2113248f, -0.5773502f, -0.2113248f, 0.7886752f, -0.5773502f, 0.5773502f, 0.5773502f, 0.57735044f);  // rotate  (fractal-zoo.yaml:39)
            vec3 p8 = v3_scale(p7, 1.3333334f);  // scale s=0.75  (fractal-zoo.yaml:40)
            real d9 = de_sierpinski(p8, 8, 2.0f);  // sierpinski iterations=8 scale=2  (fractal-zoo.yaml:37)
            real d10 = d9 * 0.75f;  // undo the scale on the distance
            d4 = SEL(d10, b3, b3 > 0.3247595f);
            m5 = SEL((real)(4.0f), (real)(0.0f), b3 > 0.3247595f);
        }
        real b11 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.75f)), v3(0.7728627f, 0.7728627f, 0.7728627f), 0.0f);  // bounding box  (fractal-zoo.yaml:21)
        real d12 = b11;
        real m13 = (real)(0.0f);
        if (M_ANY(b11 <= 0.19321567f))
        {
            vec3 p14 = v3_sub(p, v3(0.0f, 0.0f, 0.75f));  // translate x=0 y=0 z=0.75  (fractal-zoo.yaml:22)
            vec3 p15 = v3_scale(p14, 1.4285715f);  // scale s=0.7  (fractal-zoo.yaml:23)
            real d16 = de_mandelbulb_int(p15, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (fractal-zoo.yaml:20)
            real d17 = d16 * 0.7f;  // undo the scale on the distance
            d12 = SEL(d17, b11, b11 > 0.19321567f);
            m13 = SEL((real)(1.0f), (real)(0.0f), b11 > 0.19321567f);
        }
        vec3 p18 = v3_sub(p, v3(0.0f, -2.2f, 0.12f));  // translate x=0 y=-2.2 z=0.12  (fractal-zoo.yaml:49)
        real d19 = sd_torus(p18, 0.45f, 0.12f);  // torus major=0.45 minor=0.12  (fractal-zoo.yaml:46)
        real d20 = sd_capsule(p18, v3(0.0f, 0.0f, -0.3f), v3(0.0f, 0.0f, 0.5f), 0.1f);  // capsule ax=0 ay=0 az=-0.3 bx=0 by=0 bz=0.5 radius=0.1  (fractal-zoo.yaml:47)
        real d21 = d19;  // smooth_union radius=0.15  (fractal-zoo.yaml:43)
        d21 = op_blend_polynomial(d21, d20, 0.15f);
        vec3 p23 = v3_sub(p, v3(0.0f, 0.5f, -0.45f));  // translate x=0 y=0.5 z=-0.45  (fractal-zoo.yaml:53)
        real d24 = sd_box(p23, v3(4.5f, 3.0f, 0.05f), 0.0f);  // box hx=4.5 hy=3 hz=0.05 radius=0  (fractal-zoo.yaml:51)
        vec3 p25 = v3_sub(p, v3(0.0f, 0.0f, -0.2f));  // translate x=0 y=0 z=-0.2  (fractal-zoo.yaml:26)
        real d26 = sd_cylinder(p25, 0.55f, 0.2f);  // cylinder radius=0.55 half_height=0.2  (fractal-zoo.yaml:24)
        real b27 = sd_box(v3_sub(p, v3(-2.6f, 0.6f, 0.2f)), v3(0.79735565f, 0.79735565f, 0.6f), 0.0f);  // bounding box  (fractal-zoo.yaml:32)
        real d28 = b27;
        real m29 = (real)(0.0f);
        if (M_ANY(b27 <= 0.19933891f))
        {
            vec3 p30 = v3_sub(p, v3(-2.6f, 0.6f, 0.2f));  // translate x=-2.6 y=0.6 z=0.2  (fractal-zoo.yaml:35)
            vec3 p31 = v3_mat(p30, 0.9063078f, 0.42261827f, 0.0f, -0.42261827f, 0.9063078f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (fractal-zoo.yaml:34)
            vec3 p32 = v3_scale(p31, 1.6666666f);  // scale s=0.6  (fractal-zoo.yaml:33)
            real d33 = de_menger(p32, 4, 3.0f);  // menger iterations=4 scale=3  (fractal-zoo.yaml:29)
            vec3 p34 = v3_sub(p32, v3(0.7f, -0.7f, 0.7f));  // translate x=0.7 y=-0.7 z=0.7  (fractal-zoo.yaml:31)
            real d35 = sd_sphere(p34, 0.7f);  // sphere radius=0.7  (fractal-zoo.yaml:30)
            real d36 = d33;  // difference  (fractal-zoo.yaml:28)
            d36 = fmax(d36, -d35);
            real d38 = d36 * 0.6f;  // undo the scale on the distance
            d28 = SEL(d38, b27, b27 > 0.19933891f);
            m29 = SEL((real)(3.0f), (real)(0.0f), b27 > 0.19933891f);
        }
        real d39 = d4;  // union  (fractal-zoo.yaml:18)
        real m40 = m5;
        m40 = SEL(m40, m13, d12 < d39);
        d39 = fmin(d39, d12);
        m40 = SEL(m40, (real)(5.0f), d21 < d39);
        d39 = fmin(d39, d21);
        m40 = SEL(m40, (real)(2.0f), d24 < d39);
        d39 = fmin(d39, d24);
        m40 = SEL(m40, (real)(2.0f), d26 < d39);
        d39 = fmin(d39, d26);
        m40 = SEL(m40, m29, d28 < d39);
        d39 = fmin(d39, d28);
        d1 = SEL(d39, b0, b0 > 1.125f);
        m2 = SEL(m40, (real)(0.0f), b0 > 1.125f);
    }
    *mat = m2;
    return d1;
}

// ---- iteration count of the nearest fractal (0 elsewhere): the iterations AOV, once per pixel ----
real scene_iterations(TIME_PARAM vec3 p)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 0.34625f, 0.12691228f)), v3(4.5f, 3.15375f, 1.3959504f), 0.0f);  // bounding box  (fractal-zoo.yaml:18)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 1.125f))
    {
        real b3 = sd_box(v3_sub(p, v3(2.6f, 0.6f, 0.03f)), v3(1.1830126f, 1.1830126f, 1.299038f), 0.0f);  // bounding box  (fractal-zoo.yaml:38)
        real d4 = b3;
        real m5 = (real)(0.0f);
        if (M_ANY(b3 <= 0.3247595f))
        {
            vec3 p6 = v3_sub(p, v3(2.6f, 0.6f, 0.03f));  // translate x=2.6 y=0.6 z=0.03  (fractal-zoo.yaml:41)
            vec3 p7 = v3_mat(p6, 0.7886752f, -0.2113248f, -0.5773502f, -0.2113248f, 0.7886752f, -0.5773502f, 0.5773502f, 0.5773502f, 0.57735044f);  // rotate  (fractal-zoo.yaml:39)
            vec3 p8 = v3_scale(p7, 1.3333334f);  // scale s=0.75  (fractal-zoo.yaml:40)
            real d9 = de_sierpinski(p8, 8, 2.0f);  // sierpinski iterations=8 scale=2  (fractal-zoo.yaml:37)
            real it10 = (real)(8.0f);  // iteration count
            real d11 = d9 * 0.75f;  // undo the scale on the distance
            d4 = SEL(d11, b3, b3 > 0.3247595f);
            m5 = SEL(it10, (real)(0.0f), b3 > 0.3247595f);
        }
        real b12 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.75f)), v3(0.7728627f, 0.7728627f, 0.7728627f), 0.0f);  // bounding box  (fractal-zoo.yaml:21)
        real d13 = b12;
        real m14 = (real)(0.0f);
        if (M_ANY(b12 <= 0.19321567f))
        {
            vec3 p15 = v3_sub(p, v3(0.0f, 0.0f, 0.75f));  // translate x=0 y=0 z=0.75  (fractal-zoo.yaml:22)
            vec3 p16 = v3_scale(p15, 1.4285715f);  // scale s=0.7  (fractal-zoo.yaml:23)
            real d17 = de_mandelbulb_int(p16, 8, 10, 2.0f, 1.1040895f, 0, v3_splat(0.0f));  // mandelbulb power=8 iterations=10 bailout=2 method=0  (fractal-zoo.yaml:20)
            real oiter19;
            real ocount20;
            real otrap18 = trap_mandelbulb(p16, 8.0f, 10, 2.0f, 0, v3_splat(0.0f), &oiter19, &ocount20);
            real it21 = ocount20;  // iteration count
            real d22 = d17 * 0.7f;  // undo the scale on the distance
            d13 = SEL(d22, b12, b12 > 0.19321567f);
            m14 = SEL(it21, (real)(0.0f), b12 > 0.19321567f);
        }
        vec3 p23 = v3_sub(p, v3(0.0f, -2.2f, 0.12f));  // translate x=0 y=-2.2 z=0.12  (fractal-zoo.yaml:49)
        real d24 = sd_torus(p23, 0.45f, 0.12f);  // torus major=0.45 minor=0.12  (fractal-zoo.yaml:46)
        real d25 = sd_capsule(p23, v3(0.0f, 0.0f, -0.3f), v3(0.0f, 0.0f, 0.5f), 0.1f);  // capsule ax=0 ay=0 az=-0.3 bx=0 by=0 bz=0.5 radius=0.1  (fractal-zoo.yaml:47)
        real d26 = d24;  // smooth_union radius=0.15  (fractal-zoo.yaml:43)
        d26 = op_blend_polynomial(d26, d25, 0.15f);
        vec3 p28 = v3_sub(p, v3(0.0f, 0.5f, -0.45f));  // translate x=0 y=0.5 z=-0.45  (fractal-zoo.yaml:53)
        real d29 = sd_box(p28, v3(4.5f, 3.0f, 0.05f), 0.0f);  // box hx=4.5 hy=3 hz=0.05 radius=0  (fractal-zoo.yaml:51)
        vec3 p30 = v3_sub(p, v3(0.0f, 0.0f, -0.2f));  // translate x=0 y=0 z=-0.2  (fractal-zoo.yaml:26)
        real d31 = sd_cylinder(p30, 0.55f, 0.2f);  // cylinder radius=0.55 half_height=0.2  (fractal-zoo.yaml:24)
        real b32 = sd_box(v3_sub(p, v3(-2.6f, 0.6f, 0.2f)), v3(0.79735565f, 0.79735565f, 0.6f), 0.0f);  // bounding box  (fractal-zoo.yaml:32)
        real d33 = b32;
        real m34 = (real)(0.0f);
        if (M_ANY(b32 <= 0.19933891f))
        {
            vec3 p35 = v3_sub(p, v3(-2.6f, 0.6f, 0.2f));  // translate x=-2.6 y=0.6 z=0.2  (fractal-zoo.yaml:35)
            vec3 p36 = v3_mat(p35, 0.9063078f, 0.42261827f, 0.0f, -0.42261827f, 0.9063078f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (fractal-zoo.yaml:34)
            vec3 p37 = v3_scale(p36, 1.6666666f);  // scale s=0.6  (fractal-zoo.yaml:33)
            real d38 = de_menger(p37, 4, 3.0f);  // menger iterations=4 scale=3  (fractal-zoo.yaml:29)
            real it39 = (real)(4.0f);  // iteration count
            vec3 p40 = v3_sub(p37, v3(0.7f, -0.7f, 0.7f));  // translate x=0.7 y=-0.7 z=0.7  (fractal-zoo.yaml:31)
            real d41 = sd_sphere(p40, 0.7f);  // sphere radius=0.7  (fractal-zoo.yaml:30)
            real d42 = d38;  // difference  (fractal-zoo.yaml:28)
            real m43 = it39;
            d42 = fmax(d42, -d41);
            real d44 = d42 * 0.6f;  // undo the scale on the distance
            d33 = SEL(d44, b32, b32 > 0.19933891f);
            m34 = SEL(m43, (real)(0.0f), b32 > 0.19933891f);
        }
        real d45 = d4;  // union  (fractal-zoo.yaml:18)
        real m46 = m5;
        m46 = SEL(m46, m14, d13 < d45);
        d45 = fmin(d45, d13);
        m46 = SEL(m46, (real)(0.0f), d26 < d45);
        d45 = fmin(d45, d26);
        m46 = SEL(m46, (real)(0.0f), d29 < d45);
        d45 = fmin(d45, d29);
        m46 = SEL(m46, (real)(0.0f), d31 < d45);
        d45 = fmin(d45, d31);
        m46 = SEL(m46, m34, d33 < d45);
        d45 = fmin(d45, d33);
        d1 = SEL(d45, b0, b0 > 1.125f);
        m2 = SEL(m46, (real)(0.0f), b0 > 1.125f);
    }
    (void)d1;
    return m2;
}

