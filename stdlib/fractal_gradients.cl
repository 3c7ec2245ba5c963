//! fn deg_log_estimator
//! deps: vec3_ops
//! class: helper
// grad of d = 0.5 log r r / dr from the orbit's end: z, its Jacobian
// columns jx, jy, jz (grad r = J^T z / r) and the running derivative with
// its gradient.
inline vec3 deg_log_estimator(vec3 z, vec3 jx, vec3 jy, vec3 jz, real dr, vec3 gdr)
{
    real r = fmax(v3_length(z), K(1e-20f));
    vec3 gr = v3_scale(v3(v3_dot(z, jx), v3_dot(z, jy), v3_dot(z, jz)), 1.0f / r);
    real lr = log(r);
    return v3_scale(v3_sub(v3_scale(gr, (lr + 1.0f) / dr), v3_scale(gdr, lr * r / (dr * dr))), 0.5f);
}

//! fn deg_mandelbulb
//! deps: vec3_ops, deg_log_estimator
//! class: helper
// The gradient of the Mandelbulb's (julia = 0: z <- z^power + p) or
// Juliabulb's (julia = 1: + c) analytic estimator d = 0.5 log r r / dr for
// render.normals: dual, by forward-mode dual numbers carried through the
// orbit: jx, jy, jz are dz/dx, dz/dy, dz/dz, and gdr the gradient of the
// running derivative dr <- n r^(n-1) dr (+ 1), which varies with p too:
// grad dr <- n (n-1) r^(n-2) dr grad r + n r^(n-1) grad dr, grad r = J^T z / r.
// Then grad d = 0.5 ((log r + 1) grad r / dr - log r r grad dr / dr^2).
// One power step in spherical coordinates
// (r, theta, phi) -> (r^n, n theta, n phi) maps a tangent dz to
//   dR (sT cF, sT sF, cT) + R dT (cT cF, cT sF, -sT) + R dF (-sT sF, sT cF, 0)
// with dR = n r^(n-1) (z.dz)/r, dT = -n (dz_z r - z_z dr) / (r rho),
// dF = n (x dy - y dx) / rho^2, rho = |(x, y)|.
inline vec3 deg_bulb_tangent(vec3 z, vec3 dz, real r, real rho, real power, real rn, real st, real ct, real sf, real cf)
{
    real dr = v3_dot(z, dz) / r;
    real dR = power * rn / r * dr;
    real dT = -power * (dz.z * r - z.z * dr) / (r * rho);
    real dF = power * (z.x * dz.y - z.y * dz.x) / (rho * rho);
    vec3 a = v3_scale(v3(st * cf, st * sf, ct), dR);
    vec3 b = v3_scale(v3(ct * cf, ct * sf, -st), rn * dT);
    vec3 c = v3_scale(v3(-st * sf, st * cf, K(0.0f)), rn * dF);
    return v3_add(a, v3_add(b, c));
}

inline vec3 deg_mandelbulb(vec3 p, real power, int iterations, real bailout, int julia, vec3 c)
{
    vec3 add = julia ? c : p;
    real id = julia ? 0.0f : 1.0f;
    vec3 z = p;
    vec3 jx = v3(1.0f, 0.0f, 0.0f), jy = v3(0.0f, 1.0f, 0.0f), jz = v3(0.0f, 0.0f, 1.0f);
    real dr = 1.0f;
    vec3 gdr = v3_splat(0.0f);
    mask alive = v3_length(z) < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real r = fmax(v3_length(z), K(1e-20f));
        vec3 gr = v3_scale(v3(v3_dot(z, jx), v3_dot(z, jy), v3_dot(z, jz)), 1.0f / r);
        real rn1 = pow(r, power - 1.0f);
        vec3 gdr_next = v3_add(v3_scale(gr, power * (power - 1.0f) * rn1 / r * dr), v3_scale(gdr, power * rn1));
        real dr_next = power * rn1 * dr + id;
        real rho = fmax(sqrt(z.x * z.x + z.y * z.y), K(1e-20f));
        real theta = acos(clamp(z.z / r, K(-1.0f), K(1.0f))) * power;
        real phi = atan2(z.y, z.x) * power;
        real rn = pow(r, power);
        real st = sin(theta), ct = cos(theta), sf = sin(phi), cf = cos(phi);
        vec3 ax = v3_add(deg_bulb_tangent(z, jx, r, rho, power, rn, st, ct, sf, cf), v3(id, 0.0f, 0.0f));
        vec3 ay = v3_add(deg_bulb_tangent(z, jy, r, rho, power, rn, st, ct, sf, cf), v3(0.0f, id, 0.0f));
        vec3 az = v3_add(deg_bulb_tangent(z, jz, r, rho, power, rn, st, ct, sf, cf), v3(0.0f, 0.0f, id));
        vec3 z_next = v3_add(v3_scale(v3(st * cf, st * sf, ct), rn), add);
        z = v3_select(z, z_next, alive);
        jx = v3_select(jx, ax, alive);
        jy = v3_select(jy, ay, alive);
        jz = v3_select(jz, az, alive);
        dr = SEL(dr, dr_next, alive);
        gdr = v3_select(gdr, gdr_next, alive);
        alive = alive & (v3_length(z) < bailout);
    }
    return deg_log_estimator(z, jx, jy, jz, dr, gdr);
}

//! fn deg_quaternion_julia
//! deps: vec3_ops
//! class: helper
// The gradient of the quaternion Julia estimator d = 0.5 log r r / md for
// render.normals: dual, by dual numbers: the tangents of q, and grad md with
// md <- degree r^(degree-1) md. With q = (a, v) and a tangent (da, dv):
// degree 2: d(q^2) = (2a da - 2 v.dv, 2 da v + 2a dv);
// degree 3: d(q^3) = ((3a^2 - 3 v.v) da - 6a v.dv, (6a da - 2 v.dv) v + (3a^2 - v.v) dv).
// The point (x, y, z) is x + y i + z j + slice k, so the three tangents
// start as (1, 0), (0, i), (0, j).
inline void deg_quat_tangent(real a, vec3 v, int degree, real* da, vec3* dv)
{
    real vdv = v3_dot(v, *dv);
    real na, nb;
    vec3 ndv;
    if (degree == 3) {
        real vv = v3_dot(v, v);
        na = (3.0f * a * a - 3.0f * vv) * *da - 6.0f * a * vdv;
        nb = 6.0f * a * *da - 2.0f * vdv;
        ndv = v3_add(v3_scale(v, nb), v3_scale(*dv, 3.0f * a * a - vv));
    } else {
        na = 2.0f * a * *da - 2.0f * vdv;
        ndv = v3_add(v3_scale(v, 2.0f * *da), v3_scale(*dv, 2.0f * a));
    }
    *da = na;
    *dv = ndv;
}

inline vec3 deg_quaternion_julia(vec3 p, real slice, real ca, vec3 cv, int degree, int iterations, real bailout)
{
    real a = p.x;
    vec3 v = v3(p.y, p.z, slice);
    real dax = 1.0f, day = 0.0f, daz = 0.0f;
    vec3 dvx = v3_splat(0.0f), dvy = v3(1.0f, 0.0f, 0.0f), dvz = v3(0.0f, 1.0f, 0.0f);
    real md = 1.0f;
    vec3 gmd = v3_splat(0.0f);
    mask alive = a * a + v3_dot(v, v) < bailout * bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real r = fmax(sqrt(a * a + v3_dot(v, v)), K(1e-20f));
        vec3 gr = v3_scale(v3(a * dax + v3_dot(v, dvx), a * day + v3_dot(v, dvy), a * daz + v3_dot(v, dvz)), 1.0f / r);
        real rd1 = degree == 3 ? r * r : r;  // r^(degree-1)
        vec3 grd1 = degree == 3 ? v3_scale(gr, 2.0f * r) : gr;
        real md_next = (real)(degree) * rd1 * md;
        vec3 gmd_next = v3_scale(v3_add(v3_scale(grd1, md), v3_scale(gmd, rd1)), (real)(degree));
        real ax = dax, ay = day, az = daz;
        vec3 bx = dvx, by = dvy, bz = dvz;
        deg_quat_tangent(a, v, degree, &ax, &bx);
        deg_quat_tangent(a, v, degree, &ay, &by);
        deg_quat_tangent(a, v, degree, &az, &bz);
        real vv = v3_dot(v, v);
        real a_next = (degree == 3 ? a * (a * a - 3.0f * vv) : a * a - vv) + ca;
        vec3 v_next = v3_add(v3_scale(v, degree == 3 ? 3.0f * a * a - vv : 2.0f * a), cv);
        dax = SEL(dax, ax, alive); day = SEL(day, ay, alive); daz = SEL(daz, az, alive);
        dvx = v3_select(dvx, bx, alive); dvy = v3_select(dvy, by, alive); dvz = v3_select(dvz, bz, alive);
        md = SEL(md, md_next, alive);
        gmd = v3_select(gmd, gmd_next, alive);
        a = SEL(a, a_next, alive);
        v = v3_select(v, v_next, alive);
        alive = alive & (a * a + v3_dot(v, v) < bailout * bailout);
    }
    real r = fmax(sqrt(a * a + v3_dot(v, v)), K(1e-20f));
    vec3 gr = v3_scale(v3(a * dax + v3_dot(v, dvx), a * day + v3_dot(v, dvy), a * daz + v3_dot(v, dvz)), 1.0f / r);
    real lr = log(r);
    return v3_scale(v3_sub(v3_scale(gr, (lr + 1.0f) / md), v3_scale(gmd, lr * r / (md * md))), 0.5f);
}

//! fn deg_mandelbox
//! deps: vec3_ops
//! class: helper
// The gradient of the Mandelbox's estimator d = |z| / |dr| for
// render.normals: dual: the running Jacobian (columns jx, jy, jz, as for de:
// jacobian) gives grad |z| = J^T z / |z|, and the running derivative
// dr <- dr |scale| f (+ 1) changes with p where the sphere fold inverts
// (f = fixed_r2 / |w|^2, w the box-folded point): grad f = -2 f J_w^T w / |w|^2.
// grad d = grad |z| / |dr| - |z| sign(dr) grad dr / dr^2. With de: jacobian
// the same gradient serves: both estimate the same surface.
inline vec3 deg_mandelbox(vec3 p, real scale, real min_r2, real fixed_r2, real folding_limit, int iterations,
                         int julia, vec3 c, vec3 axis_scale)
{
    vec3 add = julia ? c : p;
    real id = julia ? 0.0f : 1.0f;
    real fl = folding_limit;
    vec3 z = p;
    vec3 jx = v3(1.0f, 0.0f, 0.0f), jy = v3(0.0f, 1.0f, 0.0f), jz = v3(0.0f, 0.0f, 1.0f);
    real dr = 1.0f;
    vec3 gdr = v3_splat(0.0f);
    mask alive = v3_dot(z, z) < 1e4f;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        vec3 flip = v3(SEL((real)(1.0f), (real)(-1.0f), fabs(z.x) > fl), SEL((real)(1.0f), (real)(-1.0f), fabs(z.y) > fl),
                       SEL((real)(1.0f), (real)(-1.0f), fabs(z.z) > fl));
        vec3 w = v3(clamp(z.x, -fl, fl) * 2.0f - z.x, clamp(z.y, -fl, fl) * 2.0f - z.y, clamp(z.z, -fl, fl) * 2.0f - z.z);
        vec3 ax = v3_mul(jx, flip), ay = v3_mul(jy, flip), az = v3_mul(jz, flip);
        real r2 = fmax(v3_dot(w, w), K(1e-30f));
        mask inner = r2 < min_r2;
        mask shell = !inner & (r2 < fixed_r2);
        real f = SEL(SEL((real)(1.0f), fixed_r2 / r2, shell), fixed_r2 / min_r2, inner);
        real k = SEL((real)(0.0f), 2.0f / r2, shell);
        // grad f in the shell, from the box-folded Jacobian (before the fold scales it)
        vec3 gf = v3_scale(v3(v3_dot(w, ax), v3_dot(w, ay), v3_dot(w, az)), -k * f);
        ax = v3_scale(v3_mad(ax, w, -k * v3_dot(w, ax)), f);
        ay = v3_scale(v3_mad(ay, w, -k * v3_dot(w, ay)), f);
        az = v3_scale(v3_mad(az, w, -k * v3_dot(w, az)), f);
        w = v3_scale(w, f);
        vec3 m = v3_scale(axis_scale, scale);
        vec3 z_next = v3_add(v3_mul(w, m), add);
        ax = v3_add(v3_mul(ax, m), v3(id, 0.0f, 0.0f));
        ay = v3_add(v3_mul(ay, m), v3(0.0f, id, 0.0f));
        az = v3_add(v3_mul(az, m), v3(0.0f, 0.0f, id));
        vec3 gdr_next = v3_scale(v3_add(v3_scale(gdr, f), v3_scale(gf, dr)), fabs(scale));
        real dr_next = dr * fabs(scale) * f + id;
        z = v3_select(z, z_next, alive);
        jx = v3_select(jx, ax, alive);
        jy = v3_select(jy, ay, alive);
        jz = v3_select(jz, az, alive);
        dr = SEL(dr, dr_next, alive);
        gdr = v3_select(gdr, gdr_next, alive);
        alive = alive & (v3_dot(z, z) < 1e4f);
    }
    real r = fmax(v3_length(z), K(1e-20f));
    vec3 gr = v3_scale(v3(v3_dot(z, jx), v3_dot(z, jy), v3_dot(z, jz)), 1.0f / r);
    real adr = fabs(dr);
    return v3_sub(v3_scale(gr, 1.0f / adr), v3_scale(gdr, r * sign(dr) / (dr * dr)));
}
