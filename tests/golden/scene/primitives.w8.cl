// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    vec3 p0 = v3_sub(p, v3(0.5f, 2.0f, -0.15f));  // translate x=0.5 y=2 z=-0.15  (primitives.yaml:65)
    real d1 = sd_box(p0, v3(0.6f, 0.6f, 0.6f), 0.0f);  // box hx=0.6 hy=0.6 hz=0.6 radius=0  (primitives.yaml:63)
    real d2 = sd_sphere(p0, 0.78f);  // sphere radius=0.78  (primitives.yaml:64)
    real d3 = d1;  // smooth_intersection radius=0.2  (primitives.yaml:60)
    d3 = -op_blend_polynomial(-d3, -d2, 0.2f);
    vec3 p4 = v3_sub(p, v3(2.5f, 2.0f, -0.15f));  // translate x=2.5 y=2 z=-0.15  (primitives.yaml:72)
    real d5 = sd_box(p4, v3(0.6f, 0.6f, 0.6f), 0.05f);  // box hx=0.6 hy=0.6 hz=0.6 radius=0.05  (primitives.yaml:70)
    real d6 = sd_cylinder(p4, 0.4f, 1.0f);  // cylinder radius=0.4 half_height=1  (primitives.yaml:71)
    real d7 = d5;  // smooth_difference radius=0.15  (primitives.yaml:67)
    d7 = -op_blend_polynomial(-d7, d6, 0.15f);
    vec3 p8 = v3_sub(p, v3(-2.0f, -1.0f, -0.15f));  // translate x=-2 y=-1 z=-0.15  (primitives.yaml:28)
    vec3 p9 = v3_mat(p8, 0.8660254f, 0.5f, 0.0f, -0.5f, 0.8660254f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (primitives.yaml:27)
    real d10 = sd_box(p9, v3(0.65f, 0.65f, 0.65f), 0.15f);  // box hx=0.65 hy=0.65 hz=0.65 radius=0.15  (primitives.yaml:26)
    vec3 p11 = v3_sub(p, v3(-4.0f, 2.0f, 0.1f));  // translate x=-4 y=2 z=0.1  (primitives.yaml:49)
    vec3 p12 = v3_mat(p11, 0.5f, 0.8660254f, 0.0f, -0.8660254f, 0.5f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (primitives.yaml:48)
    real d13 = sd_sphere(p12, 0.9f);  // sphere radius=0.9  (primitives.yaml:42)
    vec3 p14 = v3_sub(p12, v3(-1.41f, 0.0f, 0.0f));  // translate x=-1.41 y=0 z=0  (primitives.yaml:45)
    vec3 p15 = v3_mat(p14, 0.70710677f, 0.0f, -0.70710677f, 0.0f, 1.0f, 0.0f, 0.70710677f, 0.0f, 0.70710677f);  // rotate  (primitives.yaml:44)
    real d16 = sd_box(p15, v3(1.0f, 1.0f, 1.0f), 0.0f);  // box hx=1 hy=1 hz=1 radius=0  (primitives.yaml:43)
    vec3 p17 = v3_sub(p12, v3(-0.48f, -0.27f, 0.62f));  // translate x=-0.48 y=-0.27 z=0.62  (primitives.yaml:47)
    real d18 = sd_sphere(p17, 0.14f);  // sphere radius=0.14  (primitives.yaml:46)
    real d19 = d13;  // difference  (primitives.yaml:41)
    d19 = fmax(d19, -d16);
    d19 = fmax(d19, -d18);
    real d20 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -0.8f);  // plane nx=0 ny=0 nz=1 offset=-0.8  (primitives.yaml:20)
    vec3 p21 = v3_sub(p, v3(4.0f, -1.0f, 0.0f));  // translate x=4 y=-1 z=0  (primitives.yaml:38)
    real d22 = sd_capsule(p21, v3(-0.4f, 0.0f, -0.5f), v3(0.4f, 0.0f, 0.5f), 0.3f);  // capsule ax=-0.4 ay=0 az=-0.5 bx=0.4 by=0 bz=0.5 radius=0.3  (primitives.yaml:37)
    vec3 p23 = v3_sub(p, v3(0.0f, -1.0f, 0.0f));  // translate x=0 y=-1 z=0  (primitives.yaml:32)
    vec3 p24 = v3_mat(p23, 1.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.8660254f, 0.0f, -0.8660254f, 0.5f);  // rotate  (primitives.yaml:31)
    real d25 = sd_torus(p24, 0.6f, 0.2f);  // torus major=0.6 minor=0.2  (primitives.yaml:30)
    vec3 p26 = v3_sub(p, v3(4.4f, 2.0f, -0.1f));  // translate x=4.4 y=2 z=-0.1  (primitives.yaml:77)
    real d27 = sd_torus(p26, 0.5f, 0.45f);  // torus major=0.5 minor=0.45  (primitives.yaml:76)
    real d28 = sd_sphere(p26, 0.75f);  // sphere radius=0.75  (primitives.yaml:75)
    real d29 = d27;  // intersection  (primitives.yaml:74)
    d29 = fmax(d29, d28);
    vec3 p30 = v3_sub(p, v3(2.0f, -1.0f, -0.1f));  // translate x=2 y=-1 z=-0.1  (primitives.yaml:35)
    real d31 = sd_cylinder(p30, 0.5f, 0.7f);  // cylinder radius=0.5 half_height=0.7  (primitives.yaml:34)
    vec3 p32 = v3_sub(p, v3(-1.5f, 2.0f, 0.0f));  // translate x=-1.5 y=2 z=0  (primitives.yaml:58)
    vec3 p33 = v3_sub(p32, v3(-0.35f, 0.0f, 0.0f));  // translate x=-0.35 y=0 z=0  (primitives.yaml:55)
    real d34 = sd_sphere(p33, 0.55f);  // sphere radius=0.55  (primitives.yaml:54)
    vec3 p35 = v3_sub(p32, v3(0.45f, 0.0f, 0.25f));  // translate x=0.45 y=0 z=0.25  (primitives.yaml:57)
    real d36 = sd_sphere(p35, 0.45f);  // sphere radius=0.45  (primitives.yaml:56)
    real d37 = d34;  // smooth_union radius=0.4  (primitives.yaml:51)
    d37 = op_blend_polynomial(d37, d36, 0.4f);
    vec3 p38 = v3_sub(p, v3(-4.0f, -1.0f, 0.0f));  // translate x=-4 y=-1 z=0  (primitives.yaml:24)
    real d39 = sd_sphere(p38, 0.7f);  // sphere radius=0.7  (primitives.yaml:23)
    real d40 = d3;  // union  (primitives.yaml:19)
    d40 = fmin(d40, d7);
    d40 = fmin(d40, d10);
    d40 = fmin(d40, d19);
    d40 = fmin(d40, d20);
    d40 = fmin(d40, d22);
    d40 = fmin(d40, d25);
    d40 = fmin(d40, d29);
    d40 = fmin(d40, d31);
    d40 = fmin(d40, d37);
    d40 = fmin(d40, d39);
    (void)live;
    return d40;
}

// ---- scene distance, called: every use outside the marching loops ----
__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    vec3 p0 = v3_sub(p, v3(0.5f, 2.0f, -0.15f));  // translate x=0.5 y=2 z=-0.15  (primitives.yaml:65)
    real d1 = sd_box(p0, v3(0.6f, 0.6f, 0.6f), 0.0f);  // box hx=0.6 hy=0.6 hz=0.6 radius=0  (primitives.yaml:63)
    real d2 = sd_sphere(p0, 0.78f);  // sphere radius=0.78  (primitives.yaml:64)
    real d3 = d1;  // smooth_intersection radius=0.2  (primitives.yaml:60)
    d3 = -op_blend_polynomial(-d3, -d2, 0.2f);
    vec3 p5 = v3_sub(p, v3(2.5f, 2.0f, -0.15f));  // translate x=2.5 y=2 z=-0.15  (primitives.yaml:72)
    real d6 = sd_box(p5, v3(0.6f, 0.6f, 0.6f), 0.05f);  // box hx=0.6 hy=0.6 hz=0.6 radius=0.05  (primitives.yaml:70)
    real d7 = sd_cylinder(p5, 0.4f, 1.0f);  // cylinder radius=0.4 half_height=1  (primitives.yaml:71)
    real d8 = d6;  // smooth_difference radius=0.15  (primitives.yaml:67)
    d8 = -op_blend_polynomial(-d8, d7, 0.15f);
    vec3 p10 = v3_sub(p, v3(-2.0f, -1.0f, -0.15f));  // translate x=-2 y=-1 z=-0.15  (primitives.yaml:28)
    vec3 p11 = v3_mat(p10, 0.8660254f, 0.5f, 0.0f, -0.5f, 0.8660254f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (primitives.yaml:27)
    real d12 = sd_box(p11, v3(0.65f, 0.65f, 0.65f), 0.15f);  // box hx=0.65 hy=0.65 hz=0.65 radius=0.15  (primitives.yaml:26)
    vec3 p13 = v3_sub(p, v3(-4.0f, 2.0f, 0.1f));  // translate x=-4 y=2 z=0.1  (primitives.yaml:49)
    vec3 p14 = v3_mat(p13, 0.5f, 0.8660254f, 0.0f, -0.8660254f, 0.5f, 0.0f, 0.0f, 0.0f, 1.0f);  // rotate  (primitives.yaml:48)
    real d15 = sd_sphere(p14, 0.9f);  // sphere radius=0.9  (primitives.yaml:42)
    vec3 p16 = v3_sub(p14, v3(-1.41f, 0.0f, 0.0f));  // translate x=-1.41 y=0 z=0  (primitives.yaml:45)
    vec3 p17 = v3_mat(p16, 0.70710677f, 0.0f, -0.70710677f, 0.0f, 1.0f, 0.0f, 0.70710677f, 0.0f, 0.70710677f);  // rotate  (primitives.yaml:44)
    real d18 = sd_box(p17, v3(1.0f, 1.0f, 1.0f), 0.0f);  // box hx=1 hy=1 hz=1 radius=0  (primitives.yaml:43)
    vec3 p19 = v3_sub(p14, v3(-0.48f, -0.27f, 0.62f));  // translate x=-0.48 y=-0.27 z=0.62  (primitives.yaml:47)
    real d20 = sd_sphere(p19, 0.14f);  // sphere radius=0.14  (primitives.yaml:46)
    real d21 = d15;  // difference  (primitives.yaml:41)
    d21 = fmax(d21, -d18);
    d21 = fmax(d21, -d20);
    real d23 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -0.8f);  // plane nx=0 ny=0 nz=1 offset=-0.8  (primitives.yaml:20)
    vec3 p24 = v3_sub(p, v3(4.0f, -1.0f, 0.0f));  // translate x=4 y=-1 z=0  (primitives.yaml:38)
    real d25 = sd_capsule(p24, v3(-0.4f, 0.0f, -0.5f), v3(0.4f, 0.0f, 0.5f), 0.3f);  // capsule ax=-0.4 ay=0 az=-0.5 bx=0.4 by=0 bz=0.5 radius=0.3  (primitives.yaml:37)
    vec3 p26 = v3_sub(p, v3(0.0f, -1.0f, 0.0f));  // translate x=0 y=-1 z=0  (primitives.yaml:32)
    vec3 p27 = v3_mat(p26, 1.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.8660254f, 0.0f, -0.8660254f, 0.5f);  // rotate  (primitives.yaml:31)
    real d28 = sd_torus(p27, 0.6f, 0.2f);  // torus major=0.6 minor=0.2  (primitives.yaml:30)
    vec3 p29 = v3_sub(p, v3(4.4f, 2.0f, -0.1f));  // translate x=4.4 y=2 z=-0.1  (primitives.yaml:77)
    real d30 = sd_torus(p29, 0.5f, 0.45f);  // torus major=0.5 minor=0.45  (primitives.yaml:76)
    real d31 = sd_sphere(p29, 0.75f);  // sphere radius=0.75  (primitives.yaml:75)
    real d32 = d30;  // intersection  (primitives.yaml:74)
    d32 = fmax(d32, d31);
    vec3 p34 = v3_sub(p, v3(2.0f, -1.0f, -0.1f));  // translate x=2 y=-1 z=-0.1  (primitives.yaml:35)
    real d35 = sd_cylinder(p34, 0.5f, 0.7f);  // cylinder radius=0.5 half_height=0.7  (primitives.yaml:34)
    vec3 p36 = v3_sub(p, v3(-1.5f, 2.0f, 0.0f));  // translate x=-1.5 y=2 z=0  (primitives.yaml:58)
    vec3 p37 = v3_sub(p36, v3(-0.35f, 0.0f, 0.0f));  // translate x=-0.35 y=0 z=0  (primitives.yaml:55)
    real d38 = sd_sphere(p37, 0.55f);  // sphere radius=0.55  (primitives.yaml:54)
    vec3 p39 = v3_sub(p36, v3(0.45f, 0.0f, 0.25f));  // translate x=0.45 y=0 z=0.25  (primitives.yaml:57)
    real d40 = sd_sphere(p39, 0.45f);  // sphere radius=0.45  (primitives.yaml:56)
    real d41 = d38;  // smooth_union radius=0.4  (primitives.yaml:51)
    d41 = op_blend_polynomial(d41, d40, 0.4f);
    vec3 p43 = v3_sub(p, v3(-4.0f, -1.0f, 0.0f));  // translate x=-4 y=-1 z=0  (primitives.yaml:24)
    real d44 = sd_sphere(p43, 0.7f);  // sphere radius=0.7  (primitives.yaml:23)
    real d45 = d3;  // union  (primitives.yaml:19)
    real m46 = (real)(4.0f);
    m46 = SEL(m46, (real)(1.0f), d8 < d45);
    d45 = fmin(d45, d8);
    m46 = SEL(m46, (real)(3.0f), d12 < d45);
    d45 = fmin(d45, d12);
    m46 = SEL(m46, (real)(2.0f), d21 < d45);
    d45 = fmin(d45, d21);
    m46 = SEL(m46, (real)(5.0f), d23 < d45);
    d45 = fmin(d45, d23);
    m46 = SEL(m46, (real)(1.0f), d25 < d45);
    d45 = fmin(d45, d25);
    m46 = SEL(m46, (real)(2.0f), d28 < d45);
    d45 = fmin(d45, d28);
    m46 = SEL(m46, (real)(3.0f), d32 < d45);
    d45 = fmin(d45, d32);
    m46 = SEL(m46, (real)(4.0f), d35 < d45);
    d45 = fmin(d45, d35);
    m46 = SEL(m46, (real)(3.0f), d41 < d45);
    d45 = fmin(d45, d41);
    m46 = SEL(m46, (real)(1.0f), d44 < d45);
    d45 = fmin(d45, d44);
    *mat = m46;
    return d45;
}

