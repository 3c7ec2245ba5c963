//! fn trap_mandelbulb
//! deps: vec3_ops, hybrid_bulb_step
//! class: helper
// Orbit trap of the Mandelbulb (julia = 0) or Juliabulb (julia = 1): the
// smallest distance of the orbit to the origin and the x, y, z coordinate
// planes before it escapes (seed 000 Listing 7, seed 001 part II); the
// planes are nearer than the origin, so it is the smallest |coordinate|.
// Evaluated once per hit, never in the march, so it uses the trig power for
// every power.
inline real trap_mandelbulb(vec3 p, real power, int iterations, real bailout, int julia, vec3 c)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real trap = 1e10f;
    mask alive = v3_length(z) < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real unused = 1.0f;
        vec3 z_next = hybrid_bulb_step(z, power, add, &unused);
        z = v3_select(z, z_next, alive);
        real r = v3_length(z);
        trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
        alive = alive & (r < bailout);
    }
    return trap;
}

//! fn trap_mandelbulb_int
//! deps: vec3_ops, bulb_power_int
//! class: helper
// trap_mandelbulb for an integer power known at build time: the same orbit
// by the trig-free power (de Moivre), so the trap costs about one distance
// evaluation instead of ten rounds of acos, atan2, pow, sin and cos.
inline real trap_mandelbulb_int(vec3 p, int power, int iterations, real bailout, int julia, vec3 c)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real trap = 1e10f;
    real r = v3_length(z);
    mask alive = r < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real unused;
        vec3 z_next = v3_add(bulb_power_int_r(z, r, power, &unused), add);
        z = v3_select(z, z_next, alive);
        r = v3_length(z);
        trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
        alive = alive & (r < bailout);
    }
    return trap;
}

//! fn trap_mandelbox
//! deps: vec3_ops, mandelbox_fold
//! class: helper
// Orbit trap of the Mandelbox: the smallest |coordinate| along the orbit.
inline real trap_mandelbox(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                           int julia, vec3 c, vec3 axis_scale)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real trap = 1e10f;
    mask alive = v3_dot(z, z) < 1e4f;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real f;
        vec3 folded = mandelbox_fold(z, folding_limit, min_r2, fixed_r2, &f);
        z = v3_select(z, v3_add(v3_scale(v3_mul(folded, axis_scale), scale), add), alive);
        trap = SEL(trap, fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))), alive);
        alive = alive & (v3_dot(z, z) < 1e4f);
    }
    return trap;
}

//! fn trap_quaternion_julia
//! deps: vec3_ops
//! class: helper
// Orbit trap of the quaternion Julia set: the smallest |component| of the
// 3D part (x, y, z) along the orbit.
inline real trap_quaternion_julia(vec3 p, real slice, real ca, vec3 cv, int degree, int iterations, real bailout)
{
    real a = p.x;
    vec3 v = v3(p.y, p.z, slice);
    real trap = 1e10f;
    mask alive = a * a + v3_dot(v, v) < bailout * bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real vv = v3_dot(v, v);
        real a_next = degree == 3 ? a * (a * a - 3.0f * vv) : a * a - vv;
        real vscale = degree == 3 ? 3.0f * a * a - vv : 2.0f * a;
        vec3 v_next = v3_add(v3_scale(v, vscale), cv);
        a = SEL(a, a_next + ca, alive);
        v = v3_select(v, v_next, alive);
        real r2 = a * a + v3_dot(v, v);
        trap = SEL(trap, fmin(trap, fmin(fabs(a), fmin(fabs(v.x), fabs(v.y)))), alive);
        alive = alive & (r2 < bailout * bailout);
    }
    return trap;
}
