//! fn sdg_sphere
//! deps: vec3_ops
//! class: exact
// sd_sphere and its exact gradient (for render.normals: dual).
inline real sdg_sphere(vec3 p, real radius, vec3* g)
{
    real l = v3_length(p);
    *g = v3_scale(p, 1.0f / fmax(l, K(1e-30f)));
    return l - radius;
}

//! fn sdg_plane
//! deps: vec3_ops
//! class: exact
// sd_plane and its gradient, the normal.
inline real sdg_plane(vec3 p, vec3 n, real offset, vec3* g)
{
    *g = n;
    return v3_dot(p, n) - offset;
}

//! fn sdg_box
//! deps: vec3_ops
//! class: exact
// sd_box and its gradient: outside, along the offset from the nearest point
// of the (shrunk) box; inside, the axis of the nearest face.
inline real sdg_box(vec3 p, vec3 h, real radius, vec3* g)
{
    vec3 q = v3_add(v3_sub(v3_abs(p), h), v3_splat(radius));
    vec3 o = v3_max_s(q, K(0.0f));
    real lo = v3_length(o);
    real mq = v3_max_comp(q);
    vec3 s = v3(copysign((real)(1.0f), p.x), copysign((real)(1.0f), p.y), copysign((real)(1.0f), p.z));
    vec3 outside = v3_mul(s, v3_scale(o, 1.0f / fmax(lo, K(1e-30f))));
    mask ix = (q.x >= q.y) & (q.x >= q.z);
    mask iy = !ix & (q.y >= q.z);
    mask iz = !ix & !iy;
    vec3 inside = v3(SEL((real)(0.0f), s.x, ix), SEL((real)(0.0f), s.y, iy), SEL((real)(0.0f), s.z, iz));
    *g = v3_select(inside, outside, mq > 0.0f);
    return lo + fmin(mq, K(0.0f)) - radius;
}

//! fn sdg_torus
//! deps: vec3_ops
//! class: exact
// sd_torus and its gradient.
inline real sdg_torus(vec3 p, real major, real minor, vec3* g)
{
    real rho = sqrt(p.x * p.x + p.y * p.y);
    real ux = SEL(p.x / fmax(rho, K(1e-30f)), (real)(1.0f), rho < 1e-30f);
    real uy = SEL(p.y / fmax(rho, K(1e-30f)), (real)(0.0f), rho < 1e-30f);
    real qx = rho - major;
    real l = sqrt(qx * qx + p.z * p.z);
    real inv = 1.0f / fmax(l, K(1e-30f));
    *g = v3(qx * ux * inv, qx * uy * inv, p.z * inv);
    return l - minor;
}

//! fn sdg_cylinder
//! deps: vec3_ops
//! class: exact
// sd_cylinder and its gradient.
inline real sdg_cylinder(vec3 p, real radius, real half_height, vec3* g)
{
    real rho = sqrt(p.x * p.x + p.y * p.y);
    real ux = SEL(p.x / fmax(rho, K(1e-30f)), (real)(1.0f), rho < 1e-30f);
    real uy = SEL(p.y / fmax(rho, K(1e-30f)), (real)(0.0f), rho < 1e-30f);
    real sz = copysign((real)(1.0f), p.z);
    real dx = rho - radius, dz = fabs(p.z) - half_height;
    real ox = fmax(dx, K(0.0f)), oz = fmax(dz, K(0.0f));
    real lo = sqrt(ox * ox + oz * oz);
    real inv = 1.0f / fmax(lo, K(1e-30f));
    vec3 outside = v3(ox * ux * inv, ox * uy * inv, oz * sz * inv);
    vec3 inside = v3_select(v3(0.0f, 0.0f, sz), v3(ux, uy, 0.0f), dx > dz);
    *g = v3_select(inside, outside, fmax(dx, dz) > 0.0f);
    return fmin(fmax(dx, dz), K(0.0f)) + lo;
}

//! fn sdg_capsule
//! deps: vec3_ops
//! class: exact
// sd_capsule and its gradient.
inline real sdg_capsule(vec3 p, vec3 a, vec3 b, real radius, vec3* g)
{
    vec3 pa = v3_sub(p, a), ba = v3_sub(b, a);
    real h = clamp(v3_dot(pa, ba) / fmax(v3_dot(ba, ba), K(1e-30f)), K(0.0f), K(1.0f));
    vec3 v = v3_sub(pa, v3_scale(ba, h));
    real l = v3_length(v);
    *g = v3_scale(v, 1.0f / fmax(l, K(1e-30f)));
    return l - radius;
}

//! fn opg_smooth
//! deps: vec3_ops
//! class: helper
// Gradient of the polynomial smooth minimum (sign = 1) or maximum
// (sign = -1) of a and b with gradients ga, gb:
// d = min(a, b) - h^2 k/4, h = max(k - |a - b|, 0)/k, so
// grad d = grad min(a, b) + (h/2) sgn(a - b) (ga - gb); for the maximum the
// blend term changes sign. Returns the gradient.
inline vec3 opg_smooth(real a, real b, vec3 ga, vec3 gb, real k, real sign)
{
    real h = fmax(k - fabs(a - b), K(0.0f)) / k;
    mask pick_b = sign > 0.0f ? (b < a) : (b > a);
    vec3 g = v3_select(ga, gb, pick_b);
    real w = sign * 0.5f * h * copysign((real)(1.0f), a - b);
    return v3_add(g, v3_scale(v3_sub(ga, gb), w));
}
