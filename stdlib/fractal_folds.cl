//! fn fold_mandelbox
//! deps: vec3_ops
//! class: helper
// Tglad's Mandelbox folds without the scale and offset: the box fold
// (reflect each coordinate beyond folding_limit back into the box), then the
// sphere fold (scale by fixed_r2/min_r2 inside min_radius, invert in the
// fixed sphere between the two radii). *factor gets the sphere fold's
// scale factor per lane, 1 where it leaves the point alone.
inline vec3 fold_mandelbox(vec3 z, real folding_limit, real min_r2, real fixed_r2, real* factor)
{
    real fl = folding_limit;
    z = v3(clamp(z.x, -fl, fl) * 2.0f - z.x, clamp(z.y, -fl, fl) * 2.0f - z.y, clamp(z.z, -fl, fl) * 2.0f - z.z);
    real r2 = v3_dot(z, z);
    real f = SEL((real)(1.0f), fixed_r2 / fmax(r2, K(1e-30f)), r2 < fixed_r2);
    f = SEL(f, fixed_r2 / min_r2, r2 < min_r2);
    *factor = f;
    return v3_scale(z, f);
}

//! fn de_mandelbox
//! deps: vec3_ops, fold_mandelbox
//! class: estimate
// Mandelbox z <- scale * axis_scale * fold(z) + c, with c = p (julia = 0) or
// the constant c (julia = 1). Running scalar derivative
// dr <- dr |scale| f (+ 1 when c = p), d = |z| / |dr| (seed 001 part VI).
// A conformal step is what makes the scalar derivative valid: with an
// axis_scale other than (1, 1, 1) the step is non-conformal and this
// estimate can overshoot (seed 001 part VII); it ignores axis_scale on
// purpose, so the overshoot is measurable.
inline real de_mandelbox(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                         int julia, vec3 c, vec3 axis_scale)
{
    vec3 add = julia ? c : p;
    real dr_add = julia ? 0.0f : 1.0f;
    vec3 z = p;
    real dr = 1.0f;
    mask alive = v3_dot(z, z) < 1e4f;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real f;
        vec3 folded = fold_mandelbox(z, folding_limit, min_r2, fixed_r2, &f);
        vec3 z_next = v3_add(v3_scale(v3_mul(folded, axis_scale), scale), add);
        real dr_next = dr * fabs(scale) * f + dr_add;
        z = v3_select(z, z_next, alive);
        dr = SEL(dr, dr_next, alive);
        alive = alive & (v3_dot(z, z) < 1e4f);
    }
    return v3_length(z) / fabs(dr);
}

//! fn fold_cube
//! deps: vec3_ops
//! class: helper
// The symmetry folds of the cube: into the wedge x >= y >= z >= 0 (the
// absolute value, then a sort of the coordinates).
inline vec3 fold_cube(vec3 z)
{
    z = v3_abs(z);
    real hi = fmax(z.x, z.y), lo = fmin(z.x, z.y);
    z.x = hi; z.y = lo;
    hi = fmax(z.x, z.z); lo = fmin(z.x, z.z);
    z.x = hi; z.z = lo;
    hi = fmax(z.y, z.z); lo = fmin(z.y, z.z);
    z.y = hi; z.z = lo;
    return z;
}

//! fn fold_menger
//! deps: vec3_ops, fold_cube
//! class: helper
// One Menger iteration: fold into the wedge, scale about the corner
// (1, 1, 1) (shift = scale - 1), fold the middle layer back. Shared by
// de_menger and trap_menger.
inline vec3 fold_menger(vec3 z, real scale, real shift)
{
    z = fold_cube(z);
    z = v3_sub(v3_scale(z, scale), v3_splat(shift));
    z.z = SEL(z.z, z.z + shift, z.z < -0.5f * shift);
    return z;
}

//! fn de_menger
//! deps: vec3_ops, sd_box, fold_menger
//! class: estimate
// Menger sponge by folding (seed 001 part IV): fold into the wedge
// x >= y >= z >= 0, scale about the corner (1, 1, 1), fold the middle layer
// back, and after the last iteration take the distance to the unit cube
// divided by the accumulated scale. The cube [-1, 1]^3 holds it.
inline real de_menger(vec3 p, int iterations, real scale)
{
    vec3 z = p;
    real s = 1.0f;
    real shift = scale - 1.0f;
    for (int i = 0; i < iterations; ++i) {
        z = fold_menger(z, scale, shift);
        s = s * scale;
    }
    return sd_box(z, v3_splat(1.0f), K(0.0f)) / s;
}

//! fn fold_tetra
//! deps: vec3_ops
//! class: helper
// The three symmetry folds of the regular tetrahedron with vertices
// (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1): reflect in x+y=0, x+z=0, y+z=0
// when the point is on the negative side.
inline vec3 fold_tetra(vec3 z)
{
    mask m = (z.x + z.y) < 0.0f;
    real nx = SEL(z.x, -z.y, m), ny = SEL(z.y, -z.x, m);
    z.x = nx; z.y = ny;
    m = (z.x + z.z) < 0.0f;
    nx = SEL(z.x, -z.z, m);
    real nz = SEL(z.z, -z.x, m);
    z.x = nx; z.z = nz;
    m = (z.y + z.z) < 0.0f;
    ny = SEL(z.y, -z.z, m);
    nz = SEL(z.z, -z.y, m);
    z.y = ny; z.z = nz;
    return z;
}

//! fn de_sierpinski
//! deps: vec3_ops, fold_tetra
//! class: estimate
// Sierpinski tetrahedron, folding form (seed 001 part III): fold, scale
// about the vertex (1, 1, 1); the distance to the tetrahedron after the last
// iteration, divided by the accumulated scale.
inline real de_sierpinski(vec3 p, int iterations, real scale)
{
    vec3 z = p;
    real s = 1.0f;
    for (int i = 0; i < iterations; ++i) {
        z = fold_tetra(z);
        z = v3_sub(v3_scale(z, scale), v3_splat(scale - 1.0f));
        s = s * scale;
    }
    real tetra = (fmax(fabs(z.x + z.y) - z.z, fabs(z.x - z.y) + z.z) - 1.0f) * rsqrt(K(3.0f));
    return tetra / s;
}

//! fn fold_plane
//! deps: vec3_ops
//! class: helper
// Reflect z in the plane through the origin with unit normal n when it lies
// on the positive side.
inline vec3 fold_plane(vec3 z, vec3 n)
{
    real t = fmax(v3_dot(z, n), K(0.0f));
    return v3_mad(z, n, -2.0f * t);
}

//! fn v3_rows
//! deps: vec3_ops
//! class: helper
// The matrix with rows r0, r1, r2 applied to a.
inline vec3 v3_rows(vec3 a, vec3 r0, vec3 r1, vec3 r2) { return v3(v3_dot(r0, a), v3_dot(r1, a), v3_dot(r2, a)); }

//! fn fold_kifs
//! deps: vec3_ops, fold_tetra, fold_plane, fold_cube, v3_rows
//! class: helper
// One step of the kaleidoscopic IFS: rotate (rows b0..b2), fold by the
// symmetry group (n1, n2: the icosahedral mirror normals), scale about
// `offset`, rotate (rows a0..a2). Shared by de_kifs and trap_kifs.
inline vec3 fold_kifs(vec3 z, int symmetry, real scale, vec3 offset, vec3 n1, vec3 n2,
                      vec3 b0, vec3 b1, vec3 b2, vec3 a0, vec3 a1, vec3 a2)
{
    z = v3_rows(z, b0, b1, b2);
    if (symmetry == 0) {
        z = fold_tetra(z);
    } else if (symmetry == 2) {
        for (int k = 0; k < 3; ++k) {
            z = v3_abs(z);
            z = fold_plane(z, n1);
            z = fold_plane(z, n2);
        }
    } else {
        z = fold_cube(z);
    }
    z = v3_sub(v3_scale(z, scale), v3_scale(offset, scale - 1.0f));
    if (symmetry == 3) {
        real shift = offset.z * (scale - 1.0f);
        z.z = SEL(z.z, z.z + shift, z.z < -0.5f * shift);
    }
    z = v3_rows(z, a0, a1, a2);
    return z;
}

//! fn de_kifs
//! deps: vec3_ops, fold_kifs
//! class: estimate
// Knighty's kaleidoscopic IFS (seed 001 part IV): per iteration rotate
// (rows b0..b2), fold into the fundamental domain of the symmetry group
// (0 tetrahedral, 1 octahedral, 2 icosahedral, 3 Menger = octahedral plus
// the middle-layer fold), scale about `offset`, rotate (rows a0..a2). The
// attractor lies in the ball of radius |offset|, so after n iterations the
// balls of radius |offset| / scale^n around the orbit's copies cover it:
// d = (|z| - |offset|) / scale^n, which converges to the attractor as n grows.
inline real de_kifs(vec3 p, int symmetry, real scale, vec3 offset, int iterations,
                    vec3 b0, vec3 b1, vec3 b2, vec3 a0, vec3 a1, vec3 a2)
{
    // Mirror normals of the icosahedral group (golden ratio g): (-g, g-1, 1)
    // and (1, -g, g+1), normalised; computed in the kernel's precision.
    const scalar g = (K(1.0f) + sqrt(K(5.0f))) * K(0.5f);
    const vec3 n1 = v3_normalize(v3(-g, g - K(1.0f), K(1.0f)));
    const vec3 n2 = v3_normalize(v3(K(1.0f), -g, g + K(1.0f)));
    vec3 z = p;
    real s = 1.0f;
    for (int i = 0; i < iterations; ++i) {
        z = fold_kifs(z, symmetry, scale, offset, n1, n2, b0, b1, b2, a0, a1, a2);
        s = s * scale;
    }
    return (v3_length(z) - v3_length(offset)) / s;
}

//! fn fold_hybrid_bulb
//! deps: vec3_ops
//! class: helper
// One Mandelbulb step of a hybrid orbit: z <- z^power + c (trig form),
// dr <- power r^(power-1) dr + 1.
inline vec3 fold_hybrid_bulb(vec3 z, real power, vec3 c, real* dr)
{
    real r = fmax(v3_length(z), K(1e-20f));
    real theta = acos(clamp(z.z / r, K(-1.0f), K(1.0f))) * power;
    real phi = atan2(z.y, z.x) * power;
    real rp = pow(r, power - 1.0f);
    *dr = rp * power * *dr + 1.0f;
    real zr = rp * r;
    real st = sin(theta);
    return v3(zr * st * cos(phi) + c.x, zr * st * sin(phi) + c.y, zr * cos(theta) + c.z);
}

//! fn fold_hybrid_box
//! deps: vec3_ops, fold_mandelbox
//! class: helper
// One Mandelbox step of a hybrid orbit: z <- scale fold(z) + c,
// dr <- dr |scale| f + 1.
inline vec3 fold_hybrid_box(vec3 z, real scale, real min_r2, real fixed_r2, real folding_limit, vec3 c, real* dr)
{
    real f;
    vec3 folded = fold_mandelbox(z, folding_limit, min_r2, fixed_r2, &f);
    *dr = *dr * fabs(scale) * f + 1.0f;
    return v3_add(v3_scale(folded, scale), c);
}
