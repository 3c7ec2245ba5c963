// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    real d0 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -1.05f);  // plane nx=0 ny=0 nz=1 offset=-1.05  (animated.yaml:18)
    real b1 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.9646869f, 1.9646869f, 1.1343125f), 0.0f);  // bounding box  (animated.yaml:22)
    real d2 = b1;
    if (M_ANY(b1 <= 0.49117172f))
    {
        vec3 p3 = v3_mat(p, cos(((25.0f * time) * 0.017453292f)), sin(((25.0f * time) * 0.017453292f)), 0.0f, (-1.0f * sin(((25.0f * time) * 0.017453292f))), cos(((25.0f * time) * 0.017453292f)), 0.0f, 0.0f, 0.0f, (cos(((25.0f * time) * 0.017453292f)) + (1.0f - cos(((25.0f * time) * 0.017453292f)))));  // rotate (animated)  (animated.yaml:21)
        real d4 = de_mandelbulb(p3, (8.0f + (1.5f * sin((0.8f * time)))), 8, fmax(2.0f, fmin(64.0f, pow(2.0f, 8.0f / fmax((8.0f + (1.5f * sin((0.8f * time)))), 1.0f)))), ((8.0f + (1.5f * sin((0.8f * time)))) <= 1.25f ? 4.0f : fmin(4.0f, pow(2.0f, 1.0f / ((8.0f + (1.5f * sin((0.8f * time)))) - 1.0f)))));  // mandelbulb power="(8 + (1.5 * sin((0.8 * time))))" iterations=8 bailout=2 method=0  (animated.yaml:20)
        d2 = SEL(d4, b1, b1 > 0.49117172f);
    }
    vec3 p5 = v3_sub(p, v3(1.5f, 0.2f, (-0.35f + (0.3f * sin((2.0f * time))))));  // translate x=1.5 y=0.2 z="(-0.35 + (0.3 * sin((2 * time))))"  (animated.yaml:24)
    real d6 = sd_sphere(p5, 0.3f);  // sphere radius=0.3  (animated.yaml:23)
    vec3 p7 = v3_sub(p, v3(-2.0f, 0.8f, -0.3f));  // translate x=-2 y=0.8 z=-0.3  (animated.yaml:31)
    real d8 = sd_cylinder(p7, 0.12f, 0.8f);  // cylinder radius=0.12 half_height=0.8  (animated.yaml:30)
    real d9 = sd_box(p7, v3(0.25f, 0.25f, 0.25f), 0.0f);  // box hx=0.25 hy=0.25 hz=0.25 radius=0  (animated.yaml:29)
    real d10 = d8;  // smooth_union radius="(0.2 + (0.15 * sin((1.5 * time))))"  (animated.yaml:26)
    d10 = op_blend_polynomial(d10, d9, (0.2f + (0.15f * sin((1.5f * time)))));
    real d11 = d0;  // union  (animated.yaml:17)
    d11 = fmin(d11, d2);
    d11 = fmin(d11, d6);
    d11 = fmin(d11, d10);
    (void)live;
    return d11;
}

// ---- scene distance, called: every use outside the marching loops ----
__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    real d0 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -1.05f);  // plane nx=0 ny=0 nz=1 offset=-1.05  (animated.yaml:18)
    real b1 = sd_box(v3_sub(p, v3(0.0f, 0.0f, 0.0f)), v3(1.9646869f, 1.9646869f, 1.1343125f), 0.0f);  // bounding box  (animated.yaml:22)
    real d2 = b1;
    real m3 = (real)(0.0f);
    if (M_ANY(b1 <= 0.49117172f))
    {
        vec3 p4 = v3_mat(p, cos(((25.0f * time) * 0.017453292f)), sin(((25.0f * time) * 0.017453292f)), 0.0f, (-1.0f * sin(((25.0f * time) * 0.017453292f))), cos(((25.0f * time) * 0.017453292f)), 0.0f, 0.0f, 0.0f, (cos(((25.0f * time) * 0.017453292f)) + (1.0f - cos(((25.0f * time) * 0.017453292f)))));  // rotate (animated)  (animated.yaml:21)
        real d5 = de_mandelbulb(p4, (8.0f + (1.5f * sin((0.8f * time)))), 8, fmax(2.0f, fmin(64.0f, pow(2.0f, 8.0f / fmax((8.0f + (1.5f * sin((0.8f * time)))), 1.0f)))), ((8.0f + (1.5f * sin((0.8f * time)))) <= 1.25f ? 4.0f : fmin(4.0f, pow(2.0f, 1.0f / ((8.0f + (1.5f * sin((0.8f * time)))) - 1.0f)))));  // mandelbulb power="(8 + (1.5 * sin((0.8 * time))))" iterations=8 bailout=2 method=0  (animated.yaml:20)
        d2 = SEL(d5, b1, b1 > 0.49117172f);
        m3 = SEL((real)(1.0f), (real)(0.0f), b1 > 0.49117172f);
    }
    vec3 p6 = v3_sub(p, v3(1.5f, 0.2f, (-0.35f + (0.3f * sin((2.0f * time))))));  // translate x=1.5 y=0.2 z="(-0.35 + (0.3 * sin((2 * time))))"  (animated.yaml:24)
    real d7 = sd_sphere(p6, 0.3f);  // sphere radius=0.3  (animated.yaml:23)
    vec3 p8 = v3_sub(p, v3(-2.0f, 0.8f, -0.3f));  // translate x=-2 y=0.8 z=-0.3  (animated.yaml:31)
    real d9 = sd_cylinder(p8, 0.12f, 0.8f);  // cylinder radius=0.12 half_height=0.8  (animated.yaml:30)
    real d10 = sd_box(p8, v3(0.25f, 0.25f, 0.25f), 0.0f);  // box hx=0.25 hy=0.25 hz=0.25 radius=0  (animated.yaml:29)
    real d11 = d9;  // smooth_union radius="(0.2 + (0.15 * sin((1.5 * time))))"  (animated.yaml:26)
    d11 = op_blend_polynomial(d11, d10, (0.2f + (0.15f * sin((1.5f * time)))));
    real d13 = d0;  // union  (animated.yaml:17)
    real m14 = (real)(3.0f);
    m14 = SEL(m14, m3, d2 < d13);
    d13 = fmin(d13, d2);
    m14 = SEL(m14, (real)(2.0f), d7 < d13);
    d13 = fmin(d13, d7);
    m14 = SEL(m14, (real)(3.0f), d11 < d13);
    d13 = fmin(d13, d11);
    *mat = m14;
    return d13;
}

