// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 1.3f, -0.4305937f)), v3(4.5f, 3.5f, 1.3305937f), 0.0f);  // bounding box  (domain.yaml:20)
    real d1 = b0;
    if (M_ANY(b0 <= 1.125f))
    {
        vec3 p2 = v3_sub(p, v3(-2.6f, 0.0f, -0.1f));  // translate x=-2.6 y=0 z=-0.1  (domain.yaml:24)
        vec3 p3 = dm_twist(p2, 2, 1.5f);  // twist axis=2 rate=1.5  (domain.yaml:23)
        real d4 = sd_box(p3, v3(0.3f, 0.3f, 1.0f), 0.03f);  // box hx=0.3 hy=0.3 hz=1 radius=0.03  (domain.yaml:22)
        real o7 = dm_box_outside(p2, v3(-0.5342641f, -0.5342641f, -1.11f), v3(0.5342641f, 0.5342641f, 1.11f));  // L = 1.716 > 1 inside this box
        real b6 = dm_box_outside(p2, v3(-0.42426407f, -0.42426407f, -1.0f), v3(0.42426407f, 0.42426407f, 1.0f));  // the node's bounds
        real d5 = SEL(d4 * 0.5827263f, b6, o7 > 0.0f);  // divide by L inside, bounds distance outside
        vec3 p8 = v3_sub(p, v3(2.6f, 2.6f, -0.85f));  // translate x=2.6 y=2.6 z=-0.85  (domain.yaml:51)
        vec3 p9;  // polar_repeat axis=2 count=12  (domain.yaml:50)
        vec3 p10 = dm_polar(p8, 2, 12.0f, &p9);
        real d11 = (real)(1e+30f);
        for (int c12 = 0; c12 < 2; ++c12) {
            vec3 p13 = c12 == 0 ? p10 : p9;
            vec3 p14 = v3_sub(p13, v3(0.8f, 0.0f, 0.0f));  // translate x=0.8 y=0 z=0  (domain.yaml:49)
            real d15 = sd_box(p14, v3(0.09f, 0.17f, 0.25f), 0.04f);  // box hx=0.09 hy=0.17 hz=0.25 radius=0.04  (domain.yaml:49)
            d11 = fmin(d11, d15);
        }
        vec3 p16 = v3_sub(p, v3(2.6f, 0.0f, -0.75f));  // translate x=2.6 y=0 z=-0.75  (domain.yaml:35)
        vec3 p17 = v3_mat(p16, 1.0f, 0.0f, 0.0f, 0.0f, 6.123234e-17f, 1.0f, 0.0f, -1.0f, 6.123234e-17f);  // rotate  (domain.yaml:34)
        vec3 p18 = dm_bend(p17, 0, 0.5f);  // bend axis=0 rate=0.5  (domain.yaml:33)
        real d19 = sd_box(p18, v3(1.0f, 0.15f, 0.15f), 0.05f);  // box hx=1 hy=0.15 hz=0.15 radius=0.05  (domain.yaml:32)
        real o22 = dm_box_outside(p17, v3(-1.1223061f, -1.1223061f, -0.26111874f), v3(1.1223061f, 1.1223061f, 0.26111874f));  // L = 1.794 > 1 inside this box
        real b21 = dm_box_outside(p17, v3(-1.0111874f, -1.0111874f, -0.15f), v3(1.0111874f, 1.0111874f, 0.15f));  // the node's bounds
        real d20 = SEL(d19 * 0.55754095f, b21, o22 > 0.0f);  // divide by L inside, bounds distance outside
        vec3 p23 = v3_sub(p, v3(0.0f, 1.3f, -1.15f));  // translate x=0 y=1.3 z=-1.15  (domain.yaml:55)
        real d24 = sd_box(p23, v3(4.5f, 3.5f, 0.05f), 0.0f);  // box hx=4.5 hy=3.5 hz=0.05 radius=0  (domain.yaml:54)
        vec3 p25 = v3_sub(p, v3(0.0f, 2.6f, -0.2f));  // translate x=0 y=2.6 z=-0.2  (domain.yaml:45)
        real d26 = sd_sphere(p25, 0.85f);  // sphere radius=0.85  (domain.yaml:43)
        real d27 = d26 + ((((real)(0.07f) * sin(((real)(12.0f) * p25.x))) * sin(((real)(12.0f) * p25.y))) * sin(((real)(12.0f) * p25.z)));  // displace (((0.07 * sin((12 * x))) * sin((12 * y))) * sin((12 * z)))  (domain.yaml:44)
        real o30 = dm_box_outside(p25, v3(-1.02354f, -1.02354f, -1.02354f), v3(1.02354f, 1.02354f, 1.02354f));  // L = 2.455 > 1 inside this box
        real b29 = dm_box_outside(p25, v3(-0.9214f, -0.9214f, -0.9214f), v3(0.9214f, 0.9214f, 0.9214f));  // the node's bounds
        real d28 = SEL(d27 * 0.40734482f, b29, o30 > 0.0f);  // divide by L inside, bounds distance outside
        vec3 p31 = v3_sub(p, v3(-2.6f, 2.6f, -0.2f));  // translate x=-2.6 y=2.6 z=-0.2  (domain.yaml:41)
        real d32 = sd_sphere(p31, 0.9f);  // sphere radius=0.9  (domain.yaml:39)
        real d33 = fabs(d32) - 0.12f;  // onion thickness=0.12  (domain.yaml:39)
        real d34 = fabs(d33) - 0.04f;  // onion thickness=0.04  (domain.yaml:39)
        vec3 p35 = v3_sub(p31, v3(1.0f, -1.0f, 1.0f));  // translate x=1 y=-1 z=1  (domain.yaml:40)
        real d36 = sd_box(p35, v3(1.0f, 1.0f, 1.0f), 0.0f);  // box hx=1 hy=1 hz=1 radius=0  (domain.yaml:40)
        real d37 = d34;  // difference  (domain.yaml:38)
        d37 = fmax(d37, -d36);
        real b38 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.45f)), v3(0.66f, 0.66f, 0.66f), 0.0f);  // bounding box  (domain.yaml:30)
        real d39 = b38;
        if (M_ANY(b38 <= 0.165f))
        {
            vec3 p40 = v3_sub(p, v3(0.0f, 0.0f, -0.45f));  // translate x=0 y=0 z=-0.45  (domain.yaml:29)
            // repeat px=0.5 py=0.5 pz=0.5 nx=3 ny=3 nz=3  (domain.yaml:28)
            real nb42;
            real u41 = dm_repeat_axis(p40.x, (real)(0.5f), (real)(3.0f), &nb42);
            real nb44;
            real u43 = dm_repeat_axis(p40.y, (real)(0.5f), (real)(3.0f), &nb44);
            real nb46;
            real u45 = dm_repeat_axis(p40.z, (real)(0.5f), (real)(3.0f), &nb46);
            real d47 = (real)(1e+30f);
            for (int c48 = 0; c48 < 8; ++c48) {
                vec3 p49 = c48 == 0 ? v3(u41, u43, u45) : c48 == 1 ? v3(nb42, u43, u45) : c48 == 2 ? v3(u41, nb44, u45) : c48 == 3 ? v3(nb42, nb44, u45) : c48 == 4 ? v3(u41, u43, nb46) : c48 == 5 ? v3(nb42, u43, nb46) : c48 == 6 ? v3(u41, nb44, nb46) : v3(nb42, nb44, nb46);
                real d50 = sd_box(p49, v3(0.16f, 0.16f, 0.16f), 0.08f);  // box hx=0.16 hy=0.16 hz=0.16 radius=0.08  (domain.yaml:27)
                d47 = fmin(d47, d50);
            }
            real d51 = fmin(d47, fmin(fmin(0.34f + fabs(u41), 0.34f + fabs(u43)), 0.34f + fabs(u45)));  // copies beyond the neighbours are farther
            d39 = SEL(d51, b38, b38 > 0.165f);
        }
        real d52 = d5;  // union  (domain.yaml:20)
        d52 = fmin(d52, d11);
        d52 = fmin(d52, d20);
        d52 = fmin(d52, d24);
        d52 = fmin(d52, d28);
        d52 = fmin(d52, d37);
        d52 = fmin(d52, d39);
        d1 = SEL(d52, b0, b0 > 1.125f);
    }
    (void)live;
    return d1;
}

// ---- scene distance, called: every use outside the marching loops ----
__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    real b0 = sd_box(v3_sub(p, v3(0.0f, 1.3f, -0.4305937f)), v3(4.5f, 3.5f, 1.3305937f), 0.0f);  // bounding box  (domain.yaml:20)
    real d1 = b0;
    real m2 = (real)(0.0f);
    if (M_ANY(b0 <= 1.125f))
    {
        vec3 p3 = v3_sub(p, v3(-2.6f, 0.0f, -0.1f));  // translate x=-2.6 y=0 z=-0.1  (domain.yaml:24)
        vec3 p4 = dm_twist(p3, 2, 1.5f);  // twist axis=2 rate=1.5  (domain.yaml:23)
        real d5 = sd_box(p4, v3(0.3f, 0.3f, 1.0f), 0.03f);  // box hx=0.3 hy=0.3 hz=1 radius=0.03  (domain.yaml:22)
        real o8 = dm_box_outside(p3, v3(-0.5342641f, -0.5342641f, -1.11f), v3(0.5342641f, 0.5342641f, 1.11f));  // L = 1.716 > 1 inside this box
        real b7 = dm_box_outside(p3, v3(-0.42426407f, -0.42426407f, -1.0f), v3(0.42426407f, 0.42426407f, 1.0f));  // the node's bounds
        real d6 = SEL(d5 * 0.5827263f, b7, o8 > 0.0f);  // divide by L inside, bounds distance outside
        vec3 p9 = v3_sub(p, v3(2.6f, 2.6f, -0.85f));  // translate x=2.6 y=2.6 z=-0.85  (domain.yaml:51)
        vec3 p10;  // polar_repeat axis=2 count=12  (domain.yaml:50)
        vec3 p11 = dm_polar(p9, 2, 12.0f, &p10);
        real d12 = (real)(1e+30f);
        real m13 = (real)(0.0f);
        for (int c14 = 0; c14 < 2; ++c14) {
            vec3 p15 = c14 == 0 ? p11 : p10;
            vec3 p16 = v3_sub(p15, v3(0.8f, 0.0f, 0.0f));  // translate x=0.8 y=0 z=0  (domain.yaml:49)
            real d17 = sd_box(p16, v3(0.09f, 0.17f, 0.25f), 0.04f);  // box hx=0.09 hy=0.17 hz=0.25 radius=0.04  (domain.yaml:49)
            m13 = SEL(m13, (real)(0.0f), d17 < d12);
            d12 = fmin(d12, d17);
        }
        real m18 = SEL((real)(2.0f), m13, m13 != 0.0f);  // material id=2  (domain.yaml:52)
        vec3 p19 = v3_sub(p, v3(2.6f, 0.0f, -0.75f));  // translate x=2.6 y=0 z=-0.75  (domain.yaml:35)
        vec3 p20 = v3_mat(p19, 1.0f, 0.0f, 0.0f, 0.0f, 6.123234e-17f, 1.0f, 0.0f, -1.0f, 6.123234e-17f);  // rotate  (domain.yaml:34)
        vec3 p21 = dm_bend(p20, 0, 0.5f);  // bend axis=0 rate=0.5  (domain.yaml:33)
        real d22 = sd_box(p21, v3(1.0f, 0.15f, 0.15f), 0.05f);  // box hx=1 hy=0.15 hz=0.15 radius=0.05  (domain.yaml:32)
        real o25 = dm_box_outside(p20, v3(-1.1223061f, -1.1223061f, -0.26111874f), v3(1.1223061f, 1.1223061f, 0.26111874f));  // L = 1.794 > 1 inside this box
        real b24 = dm_box_outside(p20, v3(-1.0111874f, -1.0111874f, -0.15f), v3(1.0111874f, 1.0111874f, 0.15f));  // the node's bounds
        real d23 = SEL(d22 * 0.55754095f, b24, o25 > 0.0f);  // divide by L inside, bounds distance outside
        vec3 p26 = v3_sub(p, v3(0.0f, 1.3f, -1.15f));  // translate x=0 y=1.3 z=-1.15  (domain.yaml:55)
        real d27 = sd_box(p26, v3(4.5f, 3.5f, 0.05f), 0.0f);  // box hx=4.5 hy=3.5 hz=0.05 radius=0  (domain.yaml:54)
        vec3 p28 = v3_sub(p, v3(0.0f, 2.6f, -0.2f));  // translate x=0 y=2.6 z=-0.2  (domain.yaml:45)
        real d29 = sd_sphere(p28, 0.85f);  // sphere radius=0.85  (domain.yaml:43)
        real d30 = d29 + ((((real)(0.07f) * sin(((real)(12.0f) * p28.x))) * sin(((real)(12.0f) * p28.y))) * sin(((real)(12.0f) * p28.z)));  // displace (((0.07 * sin((12 * x))) * sin((12 * y))) * sin((12 * z)))  (domain.yaml:44)
        real o33 = dm_box_outside(p28, v3(-1.02354f, -1.02354f, -1.02354f), v3(1.02354f, 1.02354f, 1.02354f));  // L = 2.455 > 1 inside this box
        real b32 = dm_box_outside(p28, v3(-0.9214f, -0.9214f, -0.9214f), v3(0.9214f, 0.9214f, 0.9214f));  // the node's bounds
        real d31 = SEL(d30 * 0.40734482f, b32, o33 > 0.0f);  // divide by L inside, bounds distance outside
        vec3 p34 = v3_sub(p, v3(-2.6f, 2.6f, -0.2f));  // translate x=-2.6 y=2.6 z=-0.2  (domain.yaml:41)
        real d35 = sd_sphere(p34, 0.9f);  // sphere radius=0.9  (domain.yaml:39)
        real d36 = fabs(d35) - 0.12f;  // onion thickness=0.12  (domain.yaml:39)
        real d37 = fabs(d36) - 0.04f;  // onion thickness=0.04  (domain.yaml:39)
        vec3 p38 = v3_sub(p34, v3(1.0f, -1.0f, 1.0f));  // translate x=1 y=-1 z=1  (domain.yaml:40)
        real d39 = sd_box(p38, v3(1.0f, 1.0f, 1.0f), 0.0f);  // box hx=1 hy=1 hz=1 radius=0  (domain.yaml:40)
        real d40 = d37;  // difference  (domain.yaml:38)
        real m41 = (real)(4.0f);
        d40 = fmax(d40, -d39);
        real b42 = sd_box(v3_sub(p, v3(0.0f, 0.0f, -0.45f)), v3(0.66f, 0.66f, 0.66f), 0.0f);  // bounding box  (domain.yaml:30)
        real d43 = b42;
        real m44 = (real)(0.0f);
        if (M_ANY(b42 <= 0.165f))
        {
            vec3 p45 = v3_sub(p, v3(0.0f, 0.0f, -0.45f));  // translate x=0 y=0 z=-0.45  (domain.yaml:29)
            // repeat px=0.5 py=0.5 pz=0.5 nx=3 ny=3 nz=3  (domain.yaml:28)
            real nb47;
            real u46 = dm_repeat_axis(p45.x, (real)(0.5f), (real)(3.0f), &nb47);
            real nb49;
            real u48 = dm_repeat_axis(p45.y, (real)(0.5f), (real)(3.0f), &nb49);
            real nb51;
            real u50 = dm_repeat_axis(p45.z, (real)(0.5f), (real)(3.0f), &nb51);
            real d52 = (real)(1e+30f);
            real m53 = (real)(0.0f);
            for (int c54 = 0; c54 < 8; ++c54) {
                vec3 p55 = c54 == 0 ? v3(u46, u48, u50) : c54 == 1 ? v3(nb47, u48, u50) : c54 == 2 ? v3(u46, nb49, u50) : c54 == 3 ? v3(nb47, nb49, u50) : c54 == 4 ? v3(u46, u48, nb51) : c54 == 5 ? v3(nb47, u48, nb51) : c54 == 6 ? v3(u46, nb49, nb51) : v3(nb47, nb49, nb51);
                real d56 = sd_box(p55, v3(0.16f, 0.16f, 0.16f), 0.08f);  // box hx=0.16 hy=0.16 hz=0.16 radius=0.08  (domain.yaml:27)
                m53 = SEL(m53, (real)(0.0f), d56 < d52);
                d52 = fmin(d52, d56);
            }
            real d57 = fmin(d52, fmin(fmin(0.34f + fabs(u46), 0.34f + fabs(u48)), 0.34f + fabs(u50)));  // copies beyond the neighbours are farther
            real m58 = SEL((real)(3.0f), m53, m53 != 0.0f);  // material id=3  (domain.yaml:30)
            d43 = SEL(d57, b42, b42 > 0.165f);
            m44 = SEL(m58, (real)(0.0f), b42 > 0.165f);
        }
        real d59 = d6;  // union  (domain.yaml:20)
        real m60 = (real)(1.0f);
        m60 = SEL(m60, m18, d12 < d59);
        d59 = fmin(d59, d12);
        m60 = SEL(m60, (real)(2.0f), d23 < d59);
        d59 = fmin(d59, d23);
        m60 = SEL(m60, (real)(6.0f), d27 < d59);
        d59 = fmin(d59, d27);
        m60 = SEL(m60, (real)(5.0f), d31 < d59);
        d59 = fmin(d59, d31);
        m60 = SEL(m60, m41, d40 < d59);
        d59 = fmin(d59, d40);
        m60 = SEL(m60, m44, d43 < d59);
        d59 = fmin(d59, d43);
        d1 = SEL(d59, b0, b0 > 1.125f);
        m2 = SEL(m60, (real)(0.0f), b0 > 1.125f);
    }
    *mat = m2;
    return d1;
}

