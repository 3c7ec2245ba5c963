//! fn ipow_real
//! class: helper
// x^n for a non-negative integer n known when the kernel is built, by
// square-and-multiply: no power function, no log/exp.
inline __attribute__((always_inline)) real ipow_real(real x, int n)
{
    real acc = 1.0f;
    real base = x;
    for (int b = 0; b < 31; ++b) {  // a constant trip count: unrolls once n is known
        int k = n >> b;
        if (k == 0) break;
        if (k & 1) acc = acc * base;
        if (k > 1) base = base * base;
    }
    return acc;
}

//! fn cpow_int
//! class: helper
// (re + i im)^n by square-and-multiply. For a unit complex number
// cos t + i sin t this gives cos nt and sin nt without trig (de Moivre):
// the Chebyshev recurrences evaluated by repeated squaring. This chain
// (cpow_int, ipow_real, bulb_power_int_r, de_mandelbulb_int) is always
// inlined so that n arrives as a constant and the loop unrolls to a few
// multiplies; called out of line it branched on the bits of n every step
// (7% of the Mandelbulb frame).
inline __attribute__((always_inline)) void cpow_int(real re, real im, int n, real* out_re, real* out_im)
{
    real ar = 1.0f, ai = 0.0f;
    real br = re, bi = im;
    for (int b = 0; b < 31; ++b) {  // a constant trip count: unrolls once n is known
        int k = n >> b;
        if (k == 0) break;
        if (k & 1) {
            real t = ar * br - ai * bi;
            ai = ar * bi + ai * br;
            ar = t;
        }
        if (k > 1) {
            real s = br * br - bi * bi;
            bi = 2.0f * br * bi;
            br = s;
        }
    }
    *out_re = ar;
    *out_im = ai;
}

// (a + i rho)^n = A + i B rho from a and rho^2 alone: the products of
// numbers of the form p + i q rho stay of that form
// ((p + i q rho)(u + i v rho) = pu - qv rho^2 + i (pv + qu) rho), so the
// power needs no square root; B is returned, the caller multiplies by rho.
inline __attribute__((always_inline)) void cpow_int_rho(real a, real rho2, int n, real* out_re, real* out_b)
{
    real ar = 1.0f, ab = 0.0f;
    real br = a, bb = 1.0f;
    for (int b = 0; b < 31; ++b) {
        int k = n >> b;
        if (k == 0) break;
        if (k & 1) {
            real t = ar * br - ab * bb * rho2;
            ab = ar * bb + ab * br;
            ar = t;
        }
        if (k > 1) {
            real s = br * br - bb * bb * rho2;
            bb = 2.0f * br * bb;
            br = s;
        }
    }
    *out_re = ar;
    *out_b = ab;
}

//! fn fold_bulb_int
//! deps: vec3_ops, cpow_int, ipow_real
//! class: helper
// White-Nylander z^n for an integer n with no trig, given r = |z|: with
// cos t = z/r, sin t = rho/r (rho = |(x, y)|) and cos f = x/rho,
// sin f = y/rho, (z + i rho)^n = r^n (cos nt + i sin nt) needs no division,
// and the azimuth's multiples come from ((x + i y)/rho)^n. One square root
// and one division per step (the caller's r is the orbit's own); for even n
// neither the root nor the division sits on the chain from z to z^n.
// Returns z^n and sets *r_pow_n_minus_1 = r^(n-1) for the derivative.
inline __attribute__((always_inline)) vec3 bulb_power_int_r(vec3 z, real r, int n, real* r_pow_n_minus_1)
{
    real rn_cos_nt, rn_sin_nt, cos_nf, sin_nf;
    if ((n & 1) == 0) {
        // Even n: nothing on the step's critical path waits for a square
        // root. The azimuth's multiples are ((x + i y)^2 / rho^2)^(n/2)
        // (one division by rho^2), the polar part comes from rho^2
        // (cpow_int_rho), and sqrt(rho^2) runs alongside, needed only at
        // the last multiply.
        real rho2 = z.x * z.x + z.y * z.y;
        mask on_axis = rho2 < 1e-36f;  // on the z axis the azimuth is 0, as in the trig formula
        real inv_rho2 = 1.0f / fmax(rho2, K(1e-36f));
        real b;
        cpow_int_rho(z.z, rho2, n, &rn_cos_nt, &b);
        rn_sin_nt = b * sqrt(rho2);
        cpow_int(SEL((z.x * z.x - z.y * z.y) * inv_rho2, (real)(1.0f), on_axis),
                 SEL(2.0f * z.x * z.y * inv_rho2, (real)(0.0f), on_axis), n / 2, &cos_nf, &sin_nf);
    } else {
        real rho = sqrt(z.x * z.x + z.y * z.y);
        mask on_axis = rho < 1e-20f;
        real inv_rho = 1.0f / fmax(rho, K(1e-20f));
        cpow_int(z.z, rho, n, &rn_cos_nt, &rn_sin_nt);
        cpow_int(SEL(z.x * inv_rho, (real)(1.0f), on_axis), SEL(z.y * inv_rho, (real)(0.0f), on_axis), n, &cos_nf, &sin_nf);
    }
    *r_pow_n_minus_1 = ipow_real(r, n - 1);
    return v3(rn_sin_nt * cos_nf, rn_sin_nt * sin_nf, rn_cos_nt);
}

// The same when r is not at hand.
inline vec3 fold_bulb_int(vec3 z, int n, real* r_pow_n_minus_1)
{
    return bulb_power_int_r(z, v3_length(z), n, r_pow_n_minus_1);
}

//! fn fold_hybrid_bulb_int
//! deps: vec3_ops, fold_bulb_int
//! class: helper
// fold_hybrid_bulb for a whole power n, without trigonometry: one Mandelbulb
// step of a hybrid orbit, z <- z^n + c, dr <- n r^(n-1) dr + 1.
inline vec3 fold_hybrid_bulb_int(vec3 z, int n, vec3 c, real* dr)
{
    real rn1;
    vec3 zn = fold_bulb_int(z, n, &rn1);
    *dr = rn1 * (real)n * *dr + 1.0f;
    return v3_add(zn, c);
}

//! fn de_mandelbulb_int
//! deps: vec3_ops, fold_bulb_int
//! class: estimate
// The Mandelbulb (julia = 0: z <- z^n + p) or Juliabulb (julia = 1:
// z <- z^n + c) for an integer power known at build time: the analytic
// running-derivative estimator d = 0.5 log(r) r / dr with the trig-free
// power. dr <- n r^(n-1) dr (+ 1 for the Mandelbulb, whose c depends on p).
// Outside 1.5x the set radius it returns the distance to that ball.
inline __attribute__((always_inline)) real de_mandelbulb_int(vec3 p, int power, int iterations, real bailout, real set_radius, int julia, vec3 c)
{
    vec3 add = julia ? c : p;
    real dr_add = julia ? 0.0f : 1.0f;
    vec3 z = p;
    real dr = 1.0f;
    // The bailout test compares squares: the square root then feeds only the
    // derivative, and the orbit's next step need not wait for it.
    const real bailout2 = bailout * bailout;
    real r2 = v3_dot(z, z);
    mask alive = r2 < bailout2;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real rn1;
        vec3 z_next = v3_add(bulb_power_int_r(z, sqrt(r2), power, &rn1), add);
        real dr_next = rn1 * (real)((scalar)power) * dr + dr_add;
        z = v3_select(z, z_next, alive);
        dr = SEL(dr, dr_next, alive);
        r2 = v3_dot(z, z);
        alive = alive & (r2 < bailout2);
    }
    real r = sqrt(r2);
    real de = 0.5f * log(fmax(r, K(1e-20f))) * r / dr;
    real r0 = v3_length(p);
    return SEL(de, r0 - set_radius, r0 > 1.5f * set_radius);
}

//! fn de_bulb_trig
//! deps: vec3_ops
//! class: estimate
// The White-Nylander orbit z <- z^n + c for any real power, with the trig
// formula and the running derivative dr <- n r^(n-1) dr + dr_add, then
// d = 0.5 log(r) r / dr. The Mandelbulb adds c = p (so dr_add = 1), the
// Juliabulb a constant c (dr_add = 0). Lanes leave the loop as they pass the
// bailout. Beyond 1.5x the radius that holds the set the potential estimate
// overshoots, so the distance to that ball (a true lower bound) is returned.
inline real de_bulb_trig(vec3 p, vec3 c, real dr_add, real power, int iterations, real bailout, real set_radius)
{
    vec3 z = p;
    real dr = 1.0f;
    real r = v3_length(z);
    mask alive = r < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real rs = fmax(r, K(1e-20f));
        real theta = acos(clamp(z.z / rs, K(-1.0f), K(1.0f))) * power;
        real phi = atan2(z.y, z.x) * power;
        real rp = pow(rs, power - 1.0f);
        real dr_next = rp * power * dr + dr_add;
        real zr = rp * rs;
        real st = sin(theta);
        vec3 z_next = v3(zr * st * cos(phi) + c.x, zr * st * sin(phi) + c.y, zr * cos(theta) + c.z);
        z = v3_select(z, z_next, alive);
        dr = SEL(dr, dr_next, alive);
        r = v3_length(z);
        alive = alive & (r < bailout);
    }
    real de = 0.5f * log(fmax(r, K(1e-20f))) * r / dr;
    real r0 = v3_length(p);
    return SEL(de, r0 - set_radius, r0 > 1.5f * set_radius);
}

//! fn de_juliabulb
//! deps: de_bulb_trig
//! class: estimate
// The Juliabulb for any real power: z <- z^n + c (c constant, so no + 1 in dr).
inline real de_juliabulb(vec3 p, real power, int iterations, real bailout, real set_radius, vec3 c)
{
    return de_bulb_trig(p, c, 0.0f, power, iterations, bailout, set_radius);
}

//! fn de_quaternion_julia
//! deps: vec3_ops
//! class: estimate
// Quaternion Julia set q <- q^degree + c (degree 2, or the cubic of seed
// 000 Listing 4) sliced at w = slice: the point (x, y, z) is the
// quaternion x + y i + z j + slice k. For q = (a, v), q^2 = (a^2 - v.v, 2a v)
// and q^3 = (a (a^2 - 3 v.v), (3a^2 - v.v) v). The scalar running
// derivative |q'| <- degree |q|^(degree-1) |q'| gives d = 0.5 log(r) r / |q'|.
inline real de_quaternion_julia(vec3 p, real slice, real ca, vec3 cv, int degree, int iterations,
                                real bailout, real set_radius)
{
    real a = p.x;
    vec3 v = v3(p.y, p.z, slice);
    real md = 1.0f;
    real r2 = a * a + v3_dot(v, v);
    real b2 = bailout * bailout;
    mask alive = r2 < b2;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real vv = v3_dot(v, v);
        real a_next, vscale, md_next;
        if (degree == 3) {
            a_next = a * (a * a - 3.0f * vv);
            vscale = 3.0f * a * a - vv;
            md_next = 3.0f * r2 * md;
        } else {
            a_next = a * a - vv;
            vscale = 2.0f * a;
            md_next = 2.0f * sqrt(r2) * md;
        }
        vec3 v_next = v3_add(v3_scale(v, vscale), cv);
        a = SEL(a, a_next + ca, alive);
        v = v3_select(v, v_next, alive);
        md = SEL(md, md_next, alive);
        r2 = a * a + v3_dot(v, v);
        alive = alive & (r2 < b2);
    }
    real r = sqrt(r2);
    real de = 0.5f * log(fmax(r, K(1e-20f))) * r / md;
    real r0 = sqrt(v3_dot(p, p) + slice * slice);
    return SEL(de, r0 - set_radius, r0 > 1.5f * set_radius);
}
