//! fn iter_mandelbulb
//! deps: vec3_ops, hybrid_bulb_step
//! class: helper
// The escape iteration of the Mandelbulb (julia = 0) or Juliabulb
// (julia = 1) orbit of p: how many steps it took until |z| >= bailout, or
// `iterations` when it stayed bounded (the iterations AOV). Once per pixel.
inline real iter_mandelbulb(vec3 p, real power, int iterations, real bailout, int julia, vec3 c)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real n = 0.0f;
    mask alive = v3_length(z) < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real unused = 1.0f;
        z = v3_select(z, hybrid_bulb_step(z, power, add, &unused), alive);
        n = SEL(n, n + 1.0f, alive);
        alive = alive & (v3_length(z) < bailout);
    }
    return n;
}

//! fn iter_mandelbox
//! deps: vec3_ops, mandelbox_fold
//! class: helper
// The escape iteration of the Mandelbox orbit of p (|z|^2 >= 1e4, as its
// estimator), or `iterations`.
inline real iter_mandelbox(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                           int julia, vec3 c, vec3 axis_scale)
{
    vec3 add = julia ? c : p;
    vec3 z = p;
    real n = 0.0f;
    mask alive = v3_dot(z, z) < 1e4f;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real f;
        vec3 folded = mandelbox_fold(z, folding_limit, min_r2, fixed_r2, &f);
        z = v3_select(z, v3_add(v3_scale(v3_mul(folded, axis_scale), scale), add), alive);
        n = SEL(n, n + 1.0f, alive);
        alive = alive & (v3_dot(z, z) < 1e4f);
    }
    return n;
}

//! fn iter_quaternion_julia
//! deps: vec3_ops
//! class: helper
// The escape iteration of the quaternion Julia orbit of p, or `iterations`.
inline real iter_quaternion_julia(vec3 p, real slice, real ca, vec3 cv, int degree, int iterations, real bailout)
{
    real a = p.x;
    vec3 v = v3(p.y, p.z, slice);
    real n = 0.0f;
    mask alive = a * a + v3_dot(v, v) < bailout * bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real vv = v3_dot(v, v);
        real a_next = degree == 3 ? a * (a * a - 3.0f * vv) : a * a - vv;
        real vscale = degree == 3 ? 3.0f * a * a - vv : 2.0f * a;
        vec3 v_next = v3_add(v3_scale(v, vscale), cv);
        a = SEL(a, a_next + ca, alive);
        v = v3_select(v, v_next, alive);
        n = SEL(n, n + 1.0f, alive);
        alive = alive & (a * a + v3_dot(v, v) < bailout * bailout);
    }
    return n;
}
