// ---- scene distance: the marching loops inline this at every step ----
inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)
{
    vec3 p0 = v3_sub(p, v3(-3.0f, 0.0f, 0.0f));  // translate x=-3 y=0 z=0  (blends.yaml:34)
    real d1 = sd_box(p0, v3(0.4f, 0.4f, 0.4f), 0.05f);  // box hx=0.4 hy=0.4 hz=0.4 radius=0.05  (blends.yaml:32)
    vec3 p2 = v3_sub(p0, v3(0.5f, 0.0f, 0.4f));  // translate x=0.5 y=0 z=0.4  (blends.yaml:33)
    real d3 = sd_sphere(p2, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d4 = d1;  // blend_union style=0 radius=0.5 steps=1  (blends.yaml:28)
    d4 = op_blend_cubic(d4, d3, (real)(0.5f));
    vec3 p5 = v3_sub(p, v3(1.0f, 0.0f, 0.0f));  // translate x=1 y=0 z=0  (blends.yaml:47)
    real d6 = sd_sphere(p5, 0.72f);  // sphere radius=0.72  (blends.yaml:46)
    real d7 = sd_box(p5, v3(0.55f, 0.55f, 0.55f), 0.0f);  // box hx=0.55 hy=0.55 hz=0.55 radius=0  (blends.yaml:45)
    real d8 = d6;  // smooth_intersection radius=0.25  (blends.yaml:42)
    d8 = -op_blend_polynomial(-d8, -d7, 0.25f);
    vec3 p9 = v3_sub(p, v3(3.0f, 0.0f, 0.0f));  // translate x=3 y=0 z=0  (blends.yaml:53)
    real d10 = sd_box(p9, v3(0.55f, 0.55f, 0.55f), 0.05f);  // box hx=0.55 hy=0.55 hz=0.55 radius=0.05  (blends.yaml:51)
    vec3 p11 = v3_sub(p9, v3(0.0f, -0.55f, 0.3f));  // translate x=0 y=-0.55 z=0.3  (blends.yaml:52)
    real d12 = sd_sphere(p11, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d13 = d10;  // smooth_difference radius=0.2  (blends.yaml:48)
    d13 = -op_blend_polynomial(-d13, d12, 0.2f);
    vec3 p14 = v3_sub(p, v3(-1.0f, 0.0f, 0.0f));  // translate x=-1 y=0 z=0  (blends.yaml:41)
    real d15 = sd_torus(p14, 0.55f, 0.15f);  // torus major=0.55 minor=0.15  (blends.yaml:39)
    real d16 = sd_cylinder(p14, 0.2f, 0.7f);  // cylinder radius=0.2 half_height=0.7  (blends.yaml:40)
    real d17 = d15;  // blend_union style=1 radius=0.12 steps=1  (blends.yaml:35)
    d17 = op_blend_exponential(d17, d16, (real)(0.12f));
    real d18 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -0.6f);  // plane nx=0 ny=0 nz=1 offset=-0.6  (blends.yaml:60)
    vec3 p19 = v3_sub(p, v3(5.0f, 0.0f, 0.0f));  // translate x=5 y=0 z=0  (blends.yaml:59)
    vec3 p20 = v3_sub(p19, v3(-0.4f, 0.0f, 0.0f));  // translate x=-0.4 y=0 z=0  (blends.yaml:25)
    real d21 = sd_sphere(p20, 0.55f);  // sphere radius=0.55  (blends.yaml:25)
    vec3 p22 = v3_sub(p19, v3(0.4f, 0.0f, 0.3f));  // translate x=0.4 y=0 z=0.3  (blends.yaml:26)
    real d23 = sd_sphere(p22, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d24 = d21;  // blend_union style=2 radius=0.25 steps=1  (blends.yaml:54)
    d24 = op_blend_chamfer(d24, d23, (real)(0.25f));
    real d25 = d24 * 0.70710677f;  // L = 1.414 > 1: divide by L
    vec3 p26 = v3_sub(p, v3(-5.0f, 0.0f, 0.0f));  // translate x=-5 y=0 z=0  (blends.yaml:27)
    vec3 p27 = v3_sub(p26, v3(-0.4f, 0.0f, 0.0f));  // translate x=-0.4 y=0 z=0  (blends.yaml:25)
    real d28 = sd_sphere(p27, 0.55f);  // sphere radius=0.55  (blends.yaml:25)
    vec3 p29 = v3_sub(p26, v3(0.4f, 0.0f, 0.3f));  // translate x=0.4 y=0 z=0.3  (blends.yaml:26)
    real d30 = sd_sphere(p29, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d31 = d28;  // smooth_union radius=0.5  (blends.yaml:22)
    d31 = op_blend_polynomial(d31, d30, 0.5f);
    real d32 = d4;  // union  (blends.yaml:21)
    d32 = fmin(d32, d8);
    d32 = fmin(d32, d13);
    d32 = fmin(d32, d17);
    d32 = fmin(d32, d18);
    d32 = fmin(d32, d25);
    d32 = fmin(d32, d31);
    (void)live;
    return d32;
}

// ---- scene distance, called: every use outside the marching loops ----
__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }

// ---- scene distance with material: evaluated once per hit ----
real scene_dist_mat(TIME_PARAM vec3 p, real* mat)
{
    vec3 p0 = v3_sub(p, v3(-3.0f, 0.0f, 0.0f));  // translate x=-3 y=0 z=0  (blends.yaml:34)
    real d1 = sd_box(p0, v3(0.4f, 0.4f, 0.4f), 0.05f);  // box hx=0.4 hy=0.4 hz=0.4 radius=0.05  (blends.yaml:32)
    vec3 p2 = v3_sub(p0, v3(0.5f, 0.0f, 0.4f));  // translate x=0.5 y=0 z=0.4  (blends.yaml:33)
    real d3 = sd_sphere(p2, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d4 = d1;  // blend_union style=0 radius=0.5 steps=1  (blends.yaml:28)
    real m5 = (real)(3.0f);
    m5 = SEL(m5, (real)(2.0f), d3 < d4);
    d4 = op_blend_cubic(d4, d3, (real)(0.5f));
    vec3 p6 = v3_sub(p, v3(1.0f, 0.0f, 0.0f));  // translate x=1 y=0 z=0  (blends.yaml:47)
    real d7 = sd_sphere(p6, 0.72f);  // sphere radius=0.72  (blends.yaml:46)
    real d8 = sd_box(p6, v3(0.55f, 0.55f, 0.55f), 0.0f);  // box hx=0.55 hy=0.55 hz=0.55 radius=0  (blends.yaml:45)
    real d9 = d7;  // smooth_intersection radius=0.25  (blends.yaml:42)
    real m10 = (real)(1.0f);
    m10 = SEL(m10, (real)(3.0f), d8 > d9);
    d9 = -op_blend_polynomial(-d9, -d8, 0.25f);
    vec3 p11 = v3_sub(p, v3(3.0f, 0.0f, 0.0f));  // translate x=3 y=0 z=0  (blends.yaml:53)
    real d12 = sd_box(p11, v3(0.55f, 0.55f, 0.55f), 0.05f);  // box hx=0.55 hy=0.55 hz=0.55 radius=0.05  (blends.yaml:51)
    vec3 p13 = v3_sub(p11, v3(0.0f, -0.55f, 0.3f));  // translate x=0 y=-0.55 z=0.3  (blends.yaml:52)
    real d14 = sd_sphere(p13, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d15 = d12;  // smooth_difference radius=0.2  (blends.yaml:48)
    real m16 = (real)(4.0f);
    d15 = -op_blend_polynomial(-d15, d14, 0.2f);
    vec3 p17 = v3_sub(p, v3(-1.0f, 0.0f, 0.0f));  // translate x=-1 y=0 z=0  (blends.yaml:41)
    real d18 = sd_torus(p17, 0.55f, 0.15f);  // torus major=0.55 minor=0.15  (blends.yaml:39)
    real d19 = sd_cylinder(p17, 0.2f, 0.7f);  // cylinder radius=0.2 half_height=0.7  (blends.yaml:40)
    real d20 = d18;  // blend_union style=1 radius=0.12 steps=1  (blends.yaml:35)
    real m21 = (real)(4.0f);
    m21 = SEL(m21, (real)(1.0f), d19 < d20);
    d20 = op_blend_exponential(d20, d19, (real)(0.12f));
    real d22 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -0.6f);  // plane nx=0 ny=0 nz=1 offset=-0.6  (blends.yaml:60)
    vec3 p23 = v3_sub(p, v3(5.0f, 0.0f, 0.0f));  // translate x=5 y=0 z=0  (blends.yaml:59)
    vec3 p24 = v3_sub(p23, v3(-0.4f, 0.0f, 0.0f));  // translate x=-0.4 y=0 z=0  (blends.yaml:25)
    real d25 = sd_sphere(p24, 0.55f);  // sphere radius=0.55  (blends.yaml:25)
    vec3 p26 = v3_sub(p23, v3(0.4f, 0.0f, 0.3f));  // translate x=0.4 y=0 z=0.3  (blends.yaml:26)
    real d27 = sd_sphere(p26, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d28 = d25;  // blend_union style=2 radius=0.25 steps=1  (blends.yaml:54)
    real m29 = (real)(2.0f);
    m29 = SEL(m29, (real)(1.0f), d27 < d28);
    d28 = op_blend_chamfer(d28, d27, (real)(0.25f));
    real d30 = d28 * 0.70710677f;  // L = 1.414 > 1: divide by L
    vec3 p31 = v3_sub(p, v3(-5.0f, 0.0f, 0.0f));  // translate x=-5 y=0 z=0  (blends.yaml:27)
    vec3 p32 = v3_sub(p31, v3(-0.4f, 0.0f, 0.0f));  // translate x=-0.4 y=0 z=0  (blends.yaml:25)
    real d33 = sd_sphere(p32, 0.55f);  // sphere radius=0.55  (blends.yaml:25)
    vec3 p34 = v3_sub(p31, v3(0.4f, 0.0f, 0.3f));  // translate x=0.4 y=0 z=0.3  (blends.yaml:26)
    real d35 = sd_sphere(p34, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    real d36 = d33;  // smooth_union radius=0.5  (blends.yaml:22)
    real m37 = (real)(1.0f);
    m37 = SEL(m37, (real)(2.0f), d35 < d36);
    d36 = op_blend_polynomial(d36, d35, 0.5f);
    real d38 = d4;  // union  (blends.yaml:21)
    real m39 = m5;
    m39 = SEL(m39, m10, d9 < d38);
    d38 = fmin(d38, d9);
    m39 = SEL(m39, m16, d15 < d38);
    d38 = fmin(d38, d15);
    m39 = SEL(m39, m21, d20 < d38);
    d38 = fmin(d38, d20);
    m39 = SEL(m39, (real)(5.0f), d22 < d38);
    d38 = fmin(d38, d22);
    m39 = SEL(m39, m29, d30 < d38);
    d38 = fmin(d38, d30);
    m39 = SEL(m39, m37, d36 < d38);
    d38 = fmin(d38, d36);
    *mat = m39;
    return d38;
}

// ---- scene material: evaluated once per hit; smooth blends mix their children's materials ----
real scene_material(TIME_PARAM vec3 p, mat_record* out)
{
    vec3 p0 = v3_sub(p, v3(-3.0f, 0.0f, 0.0f));  // translate x=-3 y=0 z=0  (blends.yaml:34)
    real d1 = sd_box(p0, v3(0.4f, 0.4f, 0.4f), 0.05f);  // box hx=0.4 hy=0.4 hz=0.4 radius=0.05  (blends.yaml:32)
    mat_record r2;  // material 3 'yellow'
    material_of((real)(3.0f), &r2.albedo, &r2.specular, &r2.shininess);
    r2.reflectivity = (real)(0.0f);
    vec3 p3 = v3_sub(p0, v3(0.5f, 0.0f, 0.4f));  // translate x=0.5 y=0 z=0.4  (blends.yaml:33)
    real d4 = sd_sphere(p3, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    mat_record r5;  // material 2 'blue'
    material_of((real)(2.0f), &r5.albedo, &r5.specular, &r5.shininess);
    r5.reflectivity = (real)(0.0f);
    real d6 = d1;  // blend_union style=0 radius=0.5 steps=1  (blends.yaml:28)
    real m7 = (real)(3.0f);
    mat_record r8 = r2;
    r8 = mat_mix(r8, r5, op_weight_cubic(d6, d4, (real)(0.5f)));  // blend weight
    m7 = SEL(m7, (real)(2.0f), d4 < d6);
    d6 = op_blend_cubic(d6, d4, (real)(0.5f));
    vec3 p9 = v3_sub(p, v3(1.0f, 0.0f, 0.0f));  // translate x=1 y=0 z=0  (blends.yaml:47)
    real d10 = sd_sphere(p9, 0.72f);  // sphere radius=0.72  (blends.yaml:46)
    mat_record r11;  // material 1 'red'
    material_of((real)(1.0f), &r11.albedo, &r11.specular, &r11.shininess);
    r11.reflectivity = (real)(0.0f);
    real d12 = sd_box(p9, v3(0.55f, 0.55f, 0.55f), 0.0f);  // box hx=0.55 hy=0.55 hz=0.55 radius=0  (blends.yaml:45)
    mat_record r13;  // material 3 'yellow'
    material_of((real)(3.0f), &r13.albedo, &r13.specular, &r13.shininess);
    r13.reflectivity = (real)(0.0f);
    real d14 = d10;  // smooth_intersection radius=0.25  (blends.yaml:42)
    real m15 = (real)(1.0f);
    mat_record r16 = r11;
    r16 = mat_mix(r16, r13, op_weight_polynomial(-d14, -d12, (real)(0.25f)));  // blend weight
    m15 = SEL(m15, (real)(3.0f), d12 > d14);
    d14 = -op_blend_polynomial(-d14, -d12, 0.25f);
    vec3 p17 = v3_sub(p, v3(3.0f, 0.0f, 0.0f));  // translate x=3 y=0 z=0  (blends.yaml:53)
    real d18 = sd_box(p17, v3(0.55f, 0.55f, 0.55f), 0.05f);  // box hx=0.55 hy=0.55 hz=0.55 radius=0.05  (blends.yaml:51)
    mat_record r19;  // material 4 'green'
    material_of((real)(4.0f), &r19.albedo, &r19.specular, &r19.shininess);
    r19.reflectivity = (real)(0.0f);
    vec3 p20 = v3_sub(p17, v3(0.0f, -0.55f, 0.3f));  // translate x=0 y=-0.55 z=0.3  (blends.yaml:52)
    real d21 = sd_sphere(p20, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    mat_record r22;  // material 3 'yellow'
    material_of((real)(3.0f), &r22.albedo, &r22.specular, &r22.shininess);
    r22.reflectivity = (real)(0.0f);
    real d23 = d18;  // smooth_difference radius=0.2  (blends.yaml:48)
    real m24 = (real)(4.0f);
    mat_record r25 = r19;
    r25 = mat_mix(r25, r22, op_weight_polynomial(-d23, d21, (real)(0.2f)));  // blend weight
    d23 = -op_blend_polynomial(-d23, d21, 0.2f);
    vec3 p26 = v3_sub(p, v3(-1.0f, 0.0f, 0.0f));  // translate x=-1 y=0 z=0  (blends.yaml:41)
    real d27 = sd_torus(p26, 0.55f, 0.15f);  // torus major=0.55 minor=0.15  (blends.yaml:39)
    mat_record r28;  // material 4 'green'
    material_of((real)(4.0f), &r28.albedo, &r28.specular, &r28.shininess);
    r28.reflectivity = (real)(0.0f);
    real d29 = sd_cylinder(p26, 0.2f, 0.7f);  // cylinder radius=0.2 half_height=0.7  (blends.yaml:40)
    mat_record r30;  // material 1 'red'
    material_of((real)(1.0f), &r30.albedo, &r30.specular, &r30.shininess);
    r30.reflectivity = (real)(0.0f);
    real d31 = d27;  // blend_union style=1 radius=0.12 steps=1  (blends.yaml:35)
    real m32 = (real)(4.0f);
    mat_record r33 = r28;
    r33 = mat_mix(r33, r30, op_weight_exponential(d31, d29, (real)(0.12f)));  // blend weight
    m32 = SEL(m32, (real)(1.0f), d29 < d31);
    d31 = op_blend_exponential(d31, d29, (real)(0.12f));
    real d34 = sd_plane(p, v3(0.0f, 0.0f, 1.0f), -0.6f);  // plane nx=0 ny=0 nz=1 offset=-0.6  (blends.yaml:60)
    mat_record r35;  // material 5 'floor'
    material_of((real)(5.0f), &r35.albedo, &r35.specular, &r35.shininess);
    r35.reflectivity = (real)(0.0f);
    vec3 p36 = v3_sub(p, v3(5.0f, 0.0f, 0.0f));  // translate x=5 y=0 z=0  (blends.yaml:59)
    vec3 p37 = v3_sub(p36, v3(-0.4f, 0.0f, 0.0f));  // translate x=-0.4 y=0 z=0  (blends.yaml:25)
    real d38 = sd_sphere(p37, 0.55f);  // sphere radius=0.55  (blends.yaml:25)
    mat_record r39;  // material 2 'blue'
    material_of((real)(2.0f), &r39.albedo, &r39.specular, &r39.shininess);
    r39.reflectivity = (real)(0.0f);
    vec3 p40 = v3_sub(p36, v3(0.4f, 0.0f, 0.3f));  // translate x=0.4 y=0 z=0.3  (blends.yaml:26)
    real d41 = sd_sphere(p40, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    mat_record r42;  // material 1 'red'
    material_of((real)(1.0f), &r42.albedo, &r42.specular, &r42.shininess);
    r42.reflectivity = (real)(0.0f);
    real d43 = d38;  // blend_union style=2 radius=0.25 steps=1  (blends.yaml:54)
    real m44 = (real)(2.0f);
    mat_record r45 = r39;
    r45 = mat_select(r45, r42, d41 < d43);
    m44 = SEL(m44, (real)(1.0f), d41 < d43);
    d43 = op_blend_chamfer(d43, d41, (real)(0.25f));
    real d46 = d43 * 0.70710677f;  // L = 1.414 > 1: divide by L
    vec3 p47 = v3_sub(p, v3(-5.0f, 0.0f, 0.0f));  // translate x=-5 y=0 z=0  (blends.yaml:27)
    vec3 p48 = v3_sub(p47, v3(-0.4f, 0.0f, 0.0f));  // translate x=-0.4 y=0 z=0  (blends.yaml:25)
    real d49 = sd_sphere(p48, 0.55f);  // sphere radius=0.55  (blends.yaml:25)
    mat_record r50;  // material 1 'red'
    material_of((real)(1.0f), &r50.albedo, &r50.specular, &r50.shininess);
    r50.reflectivity = (real)(0.0f);
    vec3 p51 = v3_sub(p47, v3(0.4f, 0.0f, 0.3f));  // translate x=0.4 y=0 z=0.3  (blends.yaml:26)
    real d52 = sd_sphere(p51, 0.45f);  // sphere radius=0.45  (blends.yaml:26)
    mat_record r53;  // material 2 'blue'
    material_of((real)(2.0f), &r53.albedo, &r53.specular, &r53.shininess);
    r53.reflectivity = (real)(0.0f);
    real d54 = d49;  // smooth_union radius=0.5  (blends.yaml:22)
    real m55 = (real)(1.0f);
    mat_record r56 = r50;
    r56 = mat_mix(r56, r53, op_weight_polynomial(d54, d52, (real)(0.5f)));  // blend weight
    m55 = SEL(m55, (real)(2.0f), d52 < d54);
    d54 = op_blend_polynomial(d54, d52, 0.5f);
    real d57 = d6;  // union  (blends.yaml:21)
    real m58 = m7;
    mat_record r59 = r8;
    r59 = mat_select(r59, r16, d14 < d57);
    m58 = SEL(m58, m15, d14 < d57);
    d57 = fmin(d57, d14);
    r59 = mat_select(r59, r25, d23 < d57);
    m58 = SEL(m58, m24, d23 < d57);
    d57 = fmin(d57, d23);
    r59 = mat_select(r59, r33, d31 < d57);
    m58 = SEL(m58, m32, d31 < d57);
    d57 = fmin(d57, d31);
    r59 = mat_select(r59, r35, d34 < d57);
    m58 = SEL(m58, (real)(5.0f), d34 < d57);
    d57 = fmin(d57, d34);
    r59 = mat_select(r59, r45, d46 < d57);
    m58 = SEL(m58, m44, d46 < d57);
    d57 = fmin(d57, d46);
    r59 = mat_select(r59, r56, d54 < d57);
    m58 = SEL(m58, m55, d54 < d57);
    d57 = fmin(d57, d54);
    (void)d57;
    *out = r59;
    return m58;  // the nearest material's id (the material AOV)
}

