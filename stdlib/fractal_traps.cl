//! fn orbit_iteration
//! deps: vec3_ops
//! class: helper
// Smooth (continuous) iteration count of an escape-time orbit, divided by
// the iteration budget so it lies in [0, 1]: n steps taken, |z| = r past
// the escape radius R. Power-law growth (r -> r^g, the Mandelbulb, the
// quaternion Julia): n - log(log r / log R) / log g; linear growth (r -> g r,
// the Mandelbox): n - log(r / R) / log g. The fraction is 0 when r = R and 1
// when r is one step's growth past it, so the count is continuous across a
// change of n. An orbit that never escaped gets 1.
inline real orbit_iteration(real n, real r, real R, real g, int power_law, int iterations, mask escaped)
{
    real rr = fmax(r, R);
    real lR = log(fmax(R, K(1.0001f)));
    real frac = power_law ? log(log(fmax(rr, K(1.0001f))) / lR) : log(rr / R);
    frac = clamp(frac / log(fmax(g, K(1.0001f))), K(0.0f), K(1.0f));
    return SEL((real)(1.0f), (n - frac) / (real)(iterations), escaped);
}

//! fn trap_mandelbulb
//! deps: vec3_ops, fold_hybrid_bulb, orbit_iteration
//! class: helper
// Orbit trap of the Mandelbulb (julia = 0) or Juliabulb (julia = 1): the
// smallest distance of the orbit to the origin and the x, y, z coordinate
// planes before it escapes (seed 000 Listing 7, seed 001 part II); the
// planes are nearer than the origin, so it is the smallest |coordinate|.
// *iter gets the smooth iteration count (orbit_iteration), *count the
// escape iteration (steps taken until |z| >= bailout, or `iterations`: the
// iterations AOV reads it). Evaluated once per hit or pixel, never in the
// march, so it uses the trig power for every power.
inline real trap_mandelbulb(vec3 p, real power, int iterations, real bailout, int julia, vec3 c, real* iter,
                            real* count)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real trap = 1e10f, n = 0.0f, r = v3_length(z);
    mask alive = r < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real unused = 1.0f;
        vec3 z_next = fold_hybrid_bulb(z, power, add, &unused);
        z = v3_select(z, z_next, alive);
        n = SEL(n, n + 1.0f, alive);
        r = v3_length(z);
        trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
        alive = alive & (r < bailout);
    }
    *iter = orbit_iteration(n, r, bailout, power, 1, iterations, r >= bailout);
    *count = n;
    return trap;
}

//! fn trap_mandelbulb_int
//! deps: vec3_ops, fold_bulb_int, orbit_iteration
//! class: helper
// trap_mandelbulb for an integer power known at build time: the same orbit
// by the trig-free power (de Moivre), so the trap costs about one distance
// evaluation instead of ten rounds of acos, atan2, pow, sin and cos.
inline __attribute__((always_inline)) real trap_mandelbulb_int(vec3 p, int power, int iterations, real bailout, int julia, vec3 c, real* iter,
                                                               real* count)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real trap = 1e10f, n = 0.0f;
    real r = v3_length(z);
    mask alive = r < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real unused;
        vec3 z_next = v3_add(bulb_power_int_r(z, r, power, &unused), add);
        z = v3_select(z, z_next, alive);
        n = SEL(n, n + 1.0f, alive);
        r = v3_length(z);
        trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
        alive = alive & (r < bailout);
    }
    *iter = orbit_iteration(n, r, bailout, (real)(power), 1, iterations, r >= bailout);
    *count = n;
    return trap;
}

//! fn trap_mandelbox
//! deps: vec3_ops, fold_mandelbox, orbit_iteration
//! class: helper
// Orbit trap of the Mandelbox: the smallest |coordinate| along the orbit;
// *iter the smooth iteration count (linear growth by |scale|, escape at
// |z| = 100 as in the estimator), *count the escape iteration.
inline real trap_mandelbox(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                           int julia, vec3 c, vec3 axis_scale, real* iter, real* count)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real trap = 1e10f, n = 0.0f;
    mask alive = v3_dot(z, z) < 1e4f;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real f;
        vec3 folded = fold_mandelbox(z, folding_limit, min_r2, fixed_r2, &f);
        z = v3_select(z, v3_add(v3_scale(v3_mul(folded, axis_scale), scale), add), alive);
        n = SEL(n, n + 1.0f, alive);
        trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
        alive = alive & (v3_dot(z, z) < 1e4f);
    }
    real r = v3_length(z);
    *iter = orbit_iteration(n, r, K(100.0f), fabs(scale), 0, iterations, r >= 100.0f);
    *count = n;
    return trap;
}

//! fn trap_quaternion_julia
//! deps: vec3_ops, orbit_iteration
//! class: helper
// Orbit trap of the quaternion Julia set: the smallest |component| of the
// 3D part (x, y, z) along the orbit; *iter the smooth iteration count,
// *count the escape iteration.
inline real trap_quaternion_julia(vec3 p, real slice, real ca, vec3 cv, int degree, int iterations, real bailout,
                                  real* iter, real* count)
{
    real a = p.x;
    vec3 v = v3(p.y, p.z, slice);
    real trap = 1e10f, n = 0.0f;
    real r2 = a * a + v3_dot(v, v);
    mask alive = r2 < bailout * bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real vv = v3_dot(v, v);
        real a_next = degree == 3 ? a * (a * a - 3.0f * vv) : a * a - vv;
        real vscale = degree == 3 ? 3.0f * a * a - vv : 2.0f * a;
        vec3 v_next = v3_add(v3_scale(v, vscale), cv);
        a = SEL(a, a_next + ca, alive);
        v = v3_select(v, v_next, alive);
        n = SEL(n, n + 1.0f, alive);
        r2 = a * a + v3_dot(v, v);
        trap = SEL(trap, fmin(trap, fmin(fabs(a), fmin(fabs(v.x), fabs(v.y)))), alive);
        alive = alive & (r2 < bailout * bailout);
    }
    real r = sqrt(r2);
    *iter = orbit_iteration(n, r, bailout, (real)(degree), 1, iterations, r >= bailout);
    *count = n;
    return trap;
}

//! fn trap_menger
//! deps: vec3_ops, fold_menger
//! class: helper
// Orbit trap of the Menger sponge: the smallest |coordinate| of the folded,
// scaled point over the iterations (the same steps as de_menger). A fold
// fractal runs every iteration (no escape), so *iter is 1.
inline real trap_menger(vec3 p, int iterations, real scale, real* iter)
{
    vec3 z = p;
    real trap = 1e10f;
    real shift = scale - 1.0f;
    for (int i = 0; i < iterations; ++i) {
        z = fold_menger(z, scale, shift);
        trap = fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z))));
    }
    *iter = (real)(1.0f);
    return trap;
}

//! fn trap_sierpinski
//! deps: vec3_ops, fold_tetra
//! class: helper
// Orbit trap of the Sierpinski tetrahedron (the steps of de_sierpinski);
// *iter is 1 (no escape).
inline real trap_sierpinski(vec3 p, int iterations, real scale, real* iter)
{
    vec3 z = p;
    real trap = 1e10f;
    for (int i = 0; i < iterations; ++i) {
        z = fold_tetra(z);
        z = v3_sub(v3_scale(z, scale), v3_splat(scale - 1.0f));
        trap = fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z))));
    }
    *iter = (real)(1.0f);
    return trap;
}

//! fn trap_kifs
//! deps: vec3_ops, fold_kifs
//! class: helper
// Orbit trap of the kaleidoscopic IFS (the steps of de_kifs); *iter is 1
// (no escape).
inline real trap_kifs(vec3 p, int symmetry, real scale, vec3 offset, int iterations,
                      vec3 b0, vec3 b1, vec3 b2, vec3 a0, vec3 a1, vec3 a2, real* iter)
{
    const scalar g = (K(1.0f) + sqrt(K(5.0f))) * K(0.5f);
    const vec3 n1 = v3_normalize(v3(-g, g - K(1.0f), K(1.0f)));
    const vec3 n2 = v3_normalize(v3(K(1.0f), -g, g + K(1.0f)));
    vec3 z = p;
    real trap = 1e10f;
    for (int i = 0; i < iterations; ++i) {
        z = fold_kifs(z, symmetry, scale, offset, n1, n2, b0, b1, b2, a0, a1, a2);
        trap = fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z))));
    }
    *iter = (real)(1.0f);
    return trap;
}
