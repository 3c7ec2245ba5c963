//! fn fold_newton3
//! deps: vec3_ops
//! class: helper
// One Newton step for t^3 + c = 0 in Mandelbulber's triplex algebra (its
// Newton Pow3): t -> 2/3 t - c * 1/(3 s t^2), with t^-2 and the product by c
// taken the way Mandelbulber takes them. The step is not conformal; it
// returns its Jacobian's rows in *g0, *g1, *g2, carried forward through
// every intermediate (each value beside its gradient over t). Unused rows
// cost nothing once inlined. `cr` is sqrt(c.x^2 + c.y^2), `hz` c.z / cr (0
// where cr is 0: the plane part is 0 then).
inline __attribute__((always_inline)) vec3 fold_newton3(vec3 t, vec3 c, real cr, real hz, real s, real third2,
                                                        vec3* g0, vec3* g1, vec3* g2)
{
    const real x = t.x, y = t.y, zz = t.z;
    // 1 / (3 s |t|^4)
    real q = fmax(x * x + y * y + zz * zz, K(1e-30f));
    real k = 1.0f / (3.0f * s * q * q);
    vec3 gk = v3_scale(t, -4.0f * k / q);
    // t^2's factor 1 - z^2 / (x^2 + y^2) and its plane radius
    real rxy = fmax(x * x + y * y, K(1e-30f)), sr = sqrt(rxy);
    real h1 = 1.0f - zz * zz / rxy;
    vec3 gh1 = v3(2.0f * x * zz * zz / (rxy * rxy), 2.0f * y * zz * zz / (rxy * rxy), -2.0f * zz / rxy);
    // t^-2 = (h1 (x^2 - y^2), -2 h1 x y, 2 z sr) k
    real a = x * x - y * y, b = -2.0f * x * y;
    real tx = h1 * a * k, ty = h1 * b * k, tz = 2.0f * zz * sr * k;
    vec3 gtx = v3_add(v3_add(v3_scale(gh1, a * k), v3_scale(v3(2.0f * x, -2.0f * y, 0.0f), h1 * k)), v3_scale(gk, h1 * a));
    vec3 gty = v3_add(v3_add(v3_scale(gh1, b * k), v3_scale(v3(-2.0f * y, -2.0f * x, 0.0f), h1 * k)), v3_scale(gk, h1 * b));
    vec3 gtz = v3_add(v3_add(v3(0.0f, 0.0f, 2.0f * sr * k), v3_scale(v3(x / sr, y / sr, 0.0f), 2.0f * zz * k)),
                      v3_scale(gk, 2.0f * zz * sr));
    // times c: the plane part turns by c's angle and scales by h, z mixes
    real r2 = sqrt(fmax(tx * tx + ty * ty, K(1e-30f)));
    vec3 gr2 = v3_scale(v3_add(v3_scale(gtx, tx), v3_scale(gty, ty)), 1.0f / r2);
    real h = 1.0f - hz * tz / r2;
    vec3 gh = v3_scale(v3_sub(v3_scale(gtz, r2), v3_scale(gr2, tz)), -hz / (r2 * r2));
    real m = c.x * tx - c.y * ty, n = c.y * tx + c.x * ty;
    vec3 gm = v3_sub(v3_scale(gtx, c.x), v3_scale(gty, c.y)), gn = v3_add(v3_scale(gtx, c.y), v3_scale(gty, c.x));
    *g0 = v3_sub(v3(third2, 0.0f, 0.0f), v3_add(v3_scale(gm, h), v3_scale(gh, m)));
    *g1 = v3_sub(v3(0.0f, third2, 0.0f), v3_add(v3_scale(gn, h), v3_scale(gh, n)));
    *g2 = v3_sub(v3(0.0f, 0.0f, third2), v3_add(v3_scale(gtz, cr), v3_scale(gr2, c.z)));
    return v3(third2 * x - m * h, third2 * y - n * h, third2 * zz - (cr * tz + r2 * c.z));
}
