//! fn fold_sphere
//! deps: vec3_ops
//! class: helper
// A formula's sphere fold with the scalar derivative: scale by
// fixed_r2/min_r2 inside min_radius, invert in the fixed sphere between the
// radii; *dr takes the factor.
inline vec3 fold_sphere(vec3 z, real min_r2, real fixed_r2, real* dr)
{
    real r2 = v3_dot(z, z);
    real f = SEL((real)(1.0f), fixed_r2 / fmax(r2, K(1e-30f)), r2 < fixed_r2);
    f = SEL(f, fixed_r2 / min_r2, r2 < min_r2);
    *dr = *dr * f;
    return v3_scale(z, f);
}

//! fn fold_sphere_j
//! deps: vec3_ops
//! class: helper
// The sphere fold on z and the Jacobian's columns: the inner ball scales
// them, the inversion applies its derivative f (J - 2 z (z.J) / r^2).
inline void fold_sphere_j(vec3* z, vec3* ja, vec3* jb, vec3* jc, real min_r2, real fixed_r2)
{
    vec3 w = *z;
    real r2 = v3_dot(w, w);
    mask inner = r2 < min_r2;
    mask shell = !inner & (r2 < fixed_r2);
    real f = SEL(SEL((real)(1.0f), fixed_r2 / fmax(r2, K(1e-30f)), shell), fixed_r2 / min_r2, inner);
    real k = SEL((real)(0.0f), 2.0f / fmax(r2, K(1e-30f)), shell);
    *ja = v3_scale(v3_mad(*ja, w, -k * v3_dot(w, *ja)), f);
    *jb = v3_scale(v3_mad(*jb, w, -k * v3_dot(w, *jb)), f);
    *jc = v3_scale(v3_mad(*jc, w, -k * v3_dot(w, *jc)), f);
    *z = v3_scale(w, f);
}

//! fn fold_reflect_j
//! deps: vec3_ops
//! class: helper
// Where m holds, reflects z and the Jacobian's columns in the plane through
// the origin with unit normal n.
inline void fold_reflect_j(vec3* z, vec3* ja, vec3* jb, vec3* jc, vec3 n, mask m)
{
    *z = v3_select(*z, v3_mad(*z, n, -2.0f * v3_dot(*z, n)), m);
    *ja = v3_select(*ja, v3_mad(*ja, n, -2.0f * v3_dot(*ja, n)), m);
    *jb = v3_select(*jb, v3_mad(*jb, n, -2.0f * v3_dot(*jb, n)), m);
    *jc = v3_select(*jc, v3_mad(*jc, n, -2.0f * v3_dot(*jc, n)), m);
}

//! fn fold_octa_j
//! deps: vec3_ops, fold_reflect_j
//! class: helper
// fold_cube (abs, then sort x >= y >= z) on z and the Jacobian: each
// absolute value and swap is a reflection, so the columns take the same.
inline void fold_octa_j(vec3* z, vec3* ja, vec3* jb, vec3* jc)
{
    fold_reflect_j(z, ja, jb, jc, v3(1.0f, 0.0f, 0.0f), (*z).x < 0.0f);
    fold_reflect_j(z, ja, jb, jc, v3(0.0f, 1.0f, 0.0f), (*z).y < 0.0f);
    fold_reflect_j(z, ja, jb, jc, v3(0.0f, 0.0f, 1.0f), (*z).z < 0.0f);
    const real h = K(0.70710678118654752f);
    fold_reflect_j(z, ja, jb, jc, v3(-h, h, 0.0f), (*z).y > (*z).x);
    fold_reflect_j(z, ja, jb, jc, v3(-h, 0.0f, h), (*z).z > (*z).x);
    fold_reflect_j(z, ja, jb, jc, v3(0.0f, -h, h), (*z).z > (*z).y);
}

//! fn fold_tetra_j
//! deps: vec3_ops, fold_reflect_j
//! class: helper
// fold_tetra on z and the Jacobian: reflections in x+y=0, x+z=0, y+z=0.
inline void fold_tetra_j(vec3* z, vec3* ja, vec3* jb, vec3* jc)
{
    const real h = K(0.70710678118654752f);
    fold_reflect_j(z, ja, jb, jc, v3(h, h, 0.0f), (*z).x + (*z).y < 0.0f);
    fold_reflect_j(z, ja, jb, jc, v3(h, 0.0f, h), (*z).x + (*z).z < 0.0f);
    fold_reflect_j(z, ja, jb, jc, v3(0.0f, h, h), (*z).y + (*z).z < 0.0f);
}

//! fn fold_bulb
//! deps: vec3_ops
//! class: helper
// The White-Nylander power z -> r^n (sin ntheta cos nphi, sin ntheta sin nphi, cos ntheta)
// with the scalar derivative dr -> n r^(n-1) dr.
inline vec3 fold_bulb(vec3 z, real power, real* dr)
{
    real r = fmax(v3_length(z), K(1e-20f));
    real theta = acos(clamp(z.z / r, K(-1.0f), K(1.0f))) * power;
    real phi = atan2(z.y, z.x) * power;
    real rp = pow(r, power - 1.0f);
    *dr = rp * power * *dr;
    real zr = rp * r, st = sin(theta);
    return v3(zr * st * cos(phi), zr * st * sin(phi), zr * cos(theta));
}

//! fn fold_bulb_j
//! deps: vec3_ops
//! class: helper
// The power on z and the Jacobian's columns, by the chain rule through the
// spherical coordinates: a column t moves r by z.t / r, theta by
// (z_z (x t_x + y t_y) / rho - rho t_z) / r^2 and phi by (x t_y - y t_x) / rho^2.
inline void fold_bulb_j(vec3* zp, vec3* ja, vec3* jb, vec3* jc, real power)
{
    vec3 z = *zp;
    real r = fmax(v3_length(z), K(1e-20f));
    real rho2 = fmax(z.x * z.x + z.y * z.y, K(1e-30f)), rho = sqrt(rho2);
    real th = acos(clamp(z.z / r, K(-1.0f), K(1.0f))) * power;
    real ph = atan2(z.y, z.x) * power;
    real rn = pow(r, power), st = sin(th), ct = cos(th), sp = sin(ph), cp = cos(ph);
    vec3 dr_ = v3_scale(v3(st * cp, st * sp, ct), power * rn / r);
    vec3 dth = v3_scale(v3(ct * cp, ct * sp, -st), power * rn);
    vec3 dph = v3_scale(v3(-st * sp, st * cp, 0.0f), power * rn);
    vec3 cols[3] = {*ja, *jb, *jc};
    for (int k = 0; k < 3; ++k) {
        vec3 t = cols[k];
        real a = v3_dot(z, t) / r;
        real b = (z.z * (z.x * t.x + z.y * t.y) / rho - rho * t.z) / (r * r);
        real c = (z.x * t.y - z.y * t.x) / rho2;
        cols[k] = v3_add(v3_add(v3_scale(dr_, a), v3_scale(dth, b)), v3_scale(dph, c));
    }
    *ja = cols[0]; *jb = cols[1]; *jc = cols[2];
    *zp = v3(rn * st * cp, rn * st * sp, rn * ct);
}

//! fn fold_inversion_j
//! deps: vec3_ops
//! class: helper
// An inversion's derivative on the Jacobian's columns: c -> f (c - k w (w.c)),
// with w the point before it, f its factor and k = 2 / |w|^2 (0 where it
// only scales).
inline void fold_inversion_j(vec3 w, vec3* ja, vec3* jb, vec3* jc, real f, real k)
{
    *ja = v3_scale(v3_mad(*ja, w, -k * v3_dot(w, *ja)), f);
    *jb = v3_scale(v3_mad(*jb, w, -k * v3_dot(w, *jb)), f);
    *jc = v3_scale(v3_mad(*jc, w, -k * v3_dot(w, *jc)), f);
}
