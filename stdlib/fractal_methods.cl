//! fn orbit_bulb_length
//! deps: vec3_ops, fold_bulb_int, fold_hybrid_bulb
//! class: helper
// The Mandelbulb orbit of p: |z| after it passes the bailout (pin < 0), or
// after exactly `pin` steps per lane (pin >= 0: the Makin/Buddhi gradient
// needs all four taps at the same iteration count, seed 001 part V).
// ipower > 0 selects the trig-free integer power. *steps gets the count.
inline real orbit_bulb_length(vec3 p, real power, int ipower, int iterations, real bailout, real pin, real* steps)
{
    vec3 z = p;
    real r = v3_length(z);
    real n = 0.0f;
    mask free_run = pin < 0.0f;
    mask alive = SEL(n < pin, r < bailout, free_run);
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        vec3 z_next;
        if (ipower > 0) {
            real rn1;
            z_next = v3_add(fold_bulb_int(z, ipower, &rn1), p);
        } else {
            real unused = 1.0f;
            z_next = fold_hybrid_bulb(z, power, p, &unused);
        }
        z = v3_select(z, z_next, alive);
        n = SEL(n, n + 1.0f, alive);
        r = v3_length(z);
        alive = alive & SEL(n < pin, r < bailout, free_run);
    }
    *steps = n;
    return r;
}

//! fn de_mandelbulb_numeric
//! deps: vec3_ops, orbit_bulb_length
//! class: estimate
// Mandelbulb estimators from a 4-point forward-difference gradient (seed
// 001 part V), eps = 1e-4:
//   method 2 (gradient, Makin/Buddhi): r = |z_n| with n pinned for all four
//     taps, d = 0.5 r log r / |grad r|;
//   method 3 (potential, Quilez): G = log|z_n| / power^n, d = 0.5 G / |grad G|;
//   method 4 (sinh): d = 0.5 sinh(G) / (exp(G) |grad G|).
// Points that never pass the bailout are inside: 0. Beyond 1.5x the set
// radius the distance to that ball, as for the analytic estimator.
inline real de_mandelbulb_numeric(vec3 p, real power, int ipower, int iterations, real bailout, real set_radius,
                                  int method)
{
    const scalar eps = K(1e-4f);
    real n;
    real r = orbit_bulb_length(p, power, ipower, iterations, bailout, (real)(-1.0f), &n);
    real pin = method == 2 ? n : (real)(-1.0f);
    real nx, ny, nz;
    real rx = orbit_bulb_length(v3(p.x + eps, p.y, p.z), power, ipower, iterations, bailout, pin, &nx);
    real ry = orbit_bulb_length(v3(p.x, p.y + eps, p.z), power, ipower, iterations, bailout, pin, &ny);
    real rz = orbit_bulb_length(v3(p.x, p.y, p.z + eps), power, ipower, iterations, bailout, pin, &nz);
    real de;
    if (method == 2) {
        real g = v3_length(v3(rx - r, ry - r, rz - r)) / eps;
        de = 0.5f * r * log(fmax(r, K(1e-20f))) / fmax(g, K(1e-20f));
    } else {
        real G = log(fmax(r, K(1e-20f))) / pow((real)(power), n);
        real Gx = log(fmax(rx, K(1e-20f))) / pow((real)(power), nx);
        real Gy = log(fmax(ry, K(1e-20f))) / pow((real)(power), ny);
        real Gz = log(fmax(rz, K(1e-20f))) / pow((real)(power), nz);
        real g = fmax(v3_length(v3(Gx - G, Gy - G, Gz - G)) / eps, K(1e-20f));
        de = method == 3 ? 0.5f * G / g : 0.5f * sinh(G) / (exp(G) * g);
    }
    de = SEL(de, (real)(0.0f), r < bailout);
    real r0 = v3_length(p);
    return SEL(de, r0 - set_radius, r0 > 1.5f * set_radius);
}

//! fn orbit_mandelbox_jacobian
//! deps: vec3_ops
//! class: helper
// Mandelbox with a running 3x3 Jacobian by forward-mode dual numbers (seed
// 001 part VII): the columns jx, jy, jz are dz/dx, dz/dy, dz/dz. The box
// fold negates a row where it reflects, the sphere fold scales (inner
// ball) or applies the inversion's derivative f (J - 2 z (z.J) / r^2), the
// per-axis scale multiplies rows, and + p adds the identity. Then
// grad |z| = J^T z / |z|. Returns z_n; *jf2 gets the squared Frobenius
// norm of J.
inline vec3 orbit_mandelbox_jacobian(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                                     int julia, vec3 c, vec3 axis_scale, real* jf2)
{
    vec3 add = julia ? c : p;
    real id = julia ? 0.0f : 1.0f;
    real fl = folding_limit;
    vec3 z = p;
    vec3 jx = v3(1.0f, 0.0f, 0.0f), jy = v3(0.0f, 1.0f, 0.0f), jz = v3(0.0f, 0.0f, 1.0f);
    mask alive = v3_dot(z, z) < 1e4f;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        // box fold: rows of J flip sign where the coordinate is reflected
        real sx = SEL((real)(1.0f), (real)(-1.0f), fabs(z.x) > fl);
        real sy = SEL((real)(1.0f), (real)(-1.0f), fabs(z.y) > fl);
        real sz = SEL((real)(1.0f), (real)(-1.0f), fabs(z.z) > fl);
        vec3 flip = v3(sx, sy, sz);
        vec3 w = v3(clamp(z.x, -fl, fl) * 2.0f - z.x, clamp(z.y, -fl, fl) * 2.0f - z.y, clamp(z.z, -fl, fl) * 2.0f - z.z);
        vec3 ax = v3_mul(jx, flip), ay = v3_mul(jy, flip), az = v3_mul(jz, flip);
        // sphere fold
        real r2 = v3_dot(w, w);
        mask inner = r2 < min_r2;
        mask shell = !inner & (r2 < fixed_r2);
        real f = SEL(SEL((real)(1.0f), fixed_r2 / fmax(r2, K(1e-30f)), shell), fixed_r2 / min_r2, inner);
        real k = SEL((real)(0.0f), 2.0f / fmax(r2, K(1e-30f)), shell);
        ax = v3_scale(v3_mad(ax, w, -k * v3_dot(w, ax)), f);
        ay = v3_scale(v3_mad(ay, w, -k * v3_dot(w, ay)), f);
        az = v3_scale(v3_mad(az, w, -k * v3_dot(w, az)), f);
        w = v3_scale(w, f);
        // scale per axis, then + p (the identity) or + c
        vec3 m = v3_scale(axis_scale, scale);
        vec3 z_next = v3_add(v3_mul(w, m), add);
        ax = v3_add(v3_mul(ax, m), v3(id, 0.0f, 0.0f));
        ay = v3_add(v3_mul(ay, m), v3(0.0f, id, 0.0f));
        az = v3_add(v3_mul(az, m), v3(0.0f, 0.0f, id));
        z = v3_select(z, z_next, alive);
        jx = v3_select(jx, ax, alive);
        jy = v3_select(jy, ay, alive);
        jz = v3_select(jz, az, alive);
        alive = alive & (v3_dot(z, z) < 1e4f);
    }
    *jf2 = v3_dot(jx, jx) + v3_dot(jy, jy) + v3_dot(jz, jz);
    return z;
}

//! fn de_mandelbox_jacobian
//! deps: vec3_ops, orbit_mandelbox_jacobian
//! class: estimate
// The Mandelbox estimate from the running Jacobian (seed 001 part VII):
// d = |z| / ||J||, the linear estimate with the matrix norm, which bounds
// how fast |z| can change in any direction. The Frobenius norm stands in
// for the induced one (it is at least as large, at most sqrt(3) times), so
// the estimate stays on the safe side. (|z|^2 / |J^T z|, the rate along the
// gradient of |z| only, overshoots wherever that gradient nearly vanishes:
// 29 % of the rays of examples/mandelbox.yaml passed a surface with it.)
// Valid for the non-conformal Mandelbox too, where the scalar derivative
// overshoots.
inline real de_mandelbox_jacobian(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                                  int julia, vec3 c, vec3 axis_scale)
{
    real jf2;
    vec3 z = orbit_mandelbox_jacobian(p, scale, min_r2, fixed_r2, folding_limit, iterations, julia, c, axis_scale, &jf2);
    return v3_length(z) / fmax(sqrt(jf2), K(1e-30f));
}
