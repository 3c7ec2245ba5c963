//! fn sd_sphere
//! deps: vec3_ops
//! class: exact
// Sphere of the given radius at the origin.
inline real sd_sphere(vec3 p, real radius) { return v3_length(p) - radius; }

//! fn sd_box
//! deps: vec3_ops
//! class: exact
// Axis-aligned box with half extents h; edges rounded by `radius` inside the
// box (the outer size stays 2h). radius = 0 gives the sharp box.
inline real sd_box(vec3 p, vec3 h, real radius)
{
    vec3 q = v3_add(v3_sub(v3_abs(p), h), v3_splat(radius));
    return v3_length(v3_max_s(q, K(0.0f))) + fmin(v3_max_comp(q), K(0.0f)) - radius;
}

//! fn sd_torus
//! deps: vec3_ops
//! class: exact
// Torus around the z axis: ring of radius major, tube of radius minor.
inline real sd_torus(vec3 p, real major, real minor)
{
    real qx = sqrt(p.x * p.x + p.y * p.y) - major;
    return sqrt(qx * qx + p.z * p.z) - minor;
}

//! fn sd_plane
//! deps: vec3_ops
//! class: exact
// Half-space below the plane dot(p, n) = offset; n has unit length.
inline real sd_plane(vec3 p, vec3 n, real offset) { return v3_dot(p, n) - offset; }

//! fn sd_cylinder
//! deps: vec3_ops
//! class: exact
// Capped cylinder around the z axis, from z = -half_height to +half_height.
inline real sd_cylinder(vec3 p, real radius, real half_height)
{
    real dx = sqrt(p.x * p.x + p.y * p.y) - radius;
    real dz = fabs(p.z) - half_height;
    real ox = fmax(dx, K(0.0f)), oz = fmax(dz, K(0.0f));
    return fmin(fmax(dx, dz), K(0.0f)) + sqrt(ox * ox + oz * oz);
}

//! fn sd_capsule
//! deps: vec3_ops
//! class: exact
// Capsule: all points within `radius` of the segment a-b.
inline real sd_capsule(vec3 p, vec3 a, vec3 b, real radius)
{
    vec3 pa = v3_sub(p, a), ba = v3_sub(b, a);
    real h = clamp(v3_dot(pa, ba) / fmax(v3_dot(ba, ba), K(1e-30f)), K(0.0f), K(1.0f));
    return v3_length(v3_sub(pa, v3_scale(ba, h))) - radius;
}

//! fn shape_helpers
//! deps: vec3_ops
//! class: helper
// Cross product and squared length for the triangle and the quad.
inline vec3 v3_cross(vec3 a, vec3 b) { return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
inline real v3_dot2(vec3 a) { return v3_dot(a, a); }
// Squared distance from p to the segment a + t*e, t in [0, 1] (pa = p - a).
inline real sd_segment2(vec3 e, vec3 pa)
{
    real t = clamp(v3_dot(e, pa) / fmax(v3_dot2(e), K(1e-30f)), K(0.0f), K(1.0f));
    return v3_dot2(v3_sub(v3_scale(e, t), pa));
}
// 2D: inside-or-extrude helper, the exact distance of a 2D profile d2
// extruded to |z| <= h.
inline real op_extrude(real d2, real z, real h)
{
    real wy = fabs(z) - h;
    real ox = fmax(d2, K(0.0f)), oy = fmax(wy, K(0.0f));
    return fmin(fmax(d2, wy), K(0.0f)) + sqrt(ox * ox + oy * oy);
}

//! fn sd_cone
//! deps: vec3_ops
//! class: exact
// Cone around z: base disc of `radius` at z = -half_height, apex at
// z = +half_height (Quilez's exact cone, apex-centred profile q).
inline real sd_cone(vec3 p, real radius, real half_height)
{
    real wx = sqrt(p.x * p.x + p.y * p.y), wy = p.z - half_height;
    real qx = radius, qy = -2.0f * half_height;
    real t = clamp((wx * qx + wy * qy) / (qx * qx + qy * qy), K(0.0f), K(1.0f));
    real ax = wx - qx * t, ay = wy - qy * t;
    real u = clamp(wx / qx, K(0.0f), K(1.0f));
    real bx = wx - qx * u, by = wy - qy;
    real d = sqrt(fmin(ax * ax + ay * ay, bx * bx + by * by));
    real s = fmax(-(wx * qy - wy * qx), -(wy - qy));  // > 0 outside
    return SEL(d, -d, s < 0.0f);
}

//! fn sd_capped_cone
//! deps: vec3_ops
//! class: exact
// Frustum around z from z = -h (radius r1) to z = +h (radius r2).
inline real sd_capped_cone(vec3 p, real h, real r1, real r2)
{
    real qx = sqrt(p.x * p.x + p.y * p.y), qy = p.z;
    real k1x = r2, k1y = h, k2x = r2 - r1, k2y = 2.0f * h;
    real cax = qx - fmin(qx, SEL(r2, r1, qy < 0.0f)), cay = fabs(qy) - h;
    real t = clamp(((k1x - qx) * k2x + (k1y - qy) * k2y) / (k2x * k2x + k2y * k2y), K(0.0f), K(1.0f));
    real cbx = qx - k1x + k2x * t, cby = qy - k1y + k2y * t;
    real d = sqrt(fmin(cax * cax + cay * cay, cbx * cbx + cby * cby));
    return SEL(d, -d, (cbx < 0.0f) & (cay < 0.0f));
}

//! fn sd_round_cone
//! deps: vec3_ops
//! class: exact
// Convex hull of a sphere r1 at z = -h and a sphere r2 at z = +h
// (requires |r1 - r2| < 2h).
inline real sd_round_cone(vec3 p, real r1, real r2, real h)
{
    real len = 2.0f * h;
    real b = (r1 - r2) / len, a = sqrt(1.0f - b * b);
    real qx = sqrt(p.x * p.x + p.y * p.y), qy = p.z + h;
    real k = -b * qx + a * qy;
    real d0 = sqrt(qx * qx + qy * qy) - r1;
    real d1 = sqrt(qx * qx + (qy - len) * (qy - len)) - r2;
    real dm = qx * a + qy * b - r1;
    return SEL(SEL(dm, d1, k > a * len), d0, k < 0.0f);
}

//! fn sd_ellipsoid
//! deps: vec3_ops
//! class: bound
// Axis-aligned ellipsoid with semi-axes r: a bound, not exact. Quilez's
// k0 (k0 - 1) / k1 overstates the depth inside, so it is capped by
// (k0 - 1) * min(r), a bound on both sides (the ellipsoid holds the ball
// of that radius around any inner point).
inline real sd_ellipsoid(vec3 p, vec3 r)
{
    real k0 = v3_length(v3(p.x / r.x, p.y / r.y, p.z / r.z));
    real k1 = v3_length(v3(p.x / (r.x * r.x), p.y / (r.y * r.y), p.z / (r.z * r.z)));
    real rmin = fmin(r.x, fmin(r.y, r.z));
    return fmax(k0 * (k0 - 1.0f) / fmax(k1, K(1e-30f)), (k0 - 1.0f) * rmin);
}

//! fn sd_octahedron
//! deps: vec3_ops
//! class: exact
// Regular octahedron with vertices at distance s on the axes.
inline real sd_octahedron(vec3 p, real s)
{
    p = v3_abs(p);
    real m = p.x + p.y + p.z - s;
    mask mx = 3.0f * p.x < m;
    mask my = !mx & (3.0f * p.y < m);
    mask mz = !mx & !my & (3.0f * p.z < m);
    // The permutation that puts the face's nearest region first.
    real qx = SEL(SEL(p.z, p.y, my), p.x, mx);
    real qy = SEL(SEL(p.x, p.z, my), p.y, mx);
    real qz = SEL(SEL(p.y, p.x, my), p.z, mx);
    real k = fmin(fmax(0.5f * (qz - qy + s), K(0.0f)), s);
    real dq = v3_length(v3(qx, qy - s + k, qz - k));
    return SEL(m * rsqrt(K(3.0f)), dq, mx | my | mz);
}

//! fn sd_hex_prism
//! deps: vec3_ops
//! class: exact
// Hexagonal prism around z: `apothem` is the distance from the axis to a
// side face, half_height the half length along z.
inline real sd_hex_prism(vec3 p, real apothem, real half_height)
{
    // Constants from sqrt so double kernels keep full precision.
    real kx = -0.5f * sqrt(K(3.0f)), ky = 0.5f, kz = rsqrt(K(3.0f));
    p = v3_abs(p);
    real f = 2.0f * fmin(kx * p.x + ky * p.y, K(0.0f));
    real x = p.x - f * kx, y = p.y - f * ky;
    real cx = x - clamp(x, -kz * apothem, kz * apothem), cy = y - apothem;
    real l = sqrt(cx * cx + cy * cy);
    real dx = SEL(l, -l, cy < 0.0f), dy = p.z - half_height;
    real ox = fmax(dx, K(0.0f)), oy = fmax(dy, K(0.0f));
    return fmin(fmax(dx, dy), K(0.0f)) + sqrt(ox * ox + oy * oy);
}

//! fn sd_tri_prism
//! deps: shape_helpers
//! class: exact
// Equilateral triangular prism around z: vertices (+-r, -r/sqrt3) and
// (0, 2r/sqrt3), |z| <= half_height. Exact: the exact 2D triangle extruded.
inline real sd_tri_prism(vec3 p, real r, real half_height)
{
    real k = sqrt(K(3.0f));
    real x = fabs(p.x) - r, y = p.y + r / k;
    mask fold = x + k * y > 0.0f;
    real fx = 0.5f * (x - k * y), fy = 0.5f * (-k * x - y);
    x = SEL(x, fx, fold);
    y = SEL(y, fy, fold);
    x -= fmin(fmax(x, -2.0f * r), K(0.0f));
    real l = sqrt(x * x + y * y);
    return op_extrude(SEL(l, -l, y > 0.0f), p.z, half_height);
}

//! fn sd_link
//! deps: vec3_ops
//! class: exact
// Chain link in the xy plane: two half tori of radius `major` joined by
// straight parts of length 2*half_length along y, tube radius `minor`.
inline real sd_link(vec3 p, real half_length, real major, real minor)
{
    real qy = fmax(fabs(p.y) - half_length, K(0.0f));
    real ring = sqrt(p.x * p.x + qy * qy) - major;
    return sqrt(ring * ring + p.z * p.z) - minor;
}

//! fn sd_rounded_cylinder
//! deps: shape_helpers
//! class: exact
// Cylinder around z (outer radius and half height as given) whose rim is
// rounded with edge_radius.
inline real sd_rounded_cylinder(vec3 p, real radius, real half_height, real edge_radius)
{
    real dx = sqrt(p.x * p.x + p.y * p.y) - radius + edge_radius;
    return op_extrude(dx, p.z, half_height - edge_radius) - edge_radius;
}

//! fn sd_pyramid
//! deps: vec3_ops
//! class: exact
// Square pyramid: base side `base` at z = -height/2, apex at z = +height/2
// (Quilez's unit-base pyramid, scaled by the base). His formula measures to
// the sloping faces only; the base face is added: below it the distance is
// to the base square, inside no deeper than the height above it.
inline real sd_pyramid(vec3 p, real base, real height)
{
    real inv = 1.0f / base, h = height * inv;
    real ax = fabs(p.x) * inv, az = fabs(p.y) * inv, y = (p.z + 0.5f * height) * inv;
    real m2 = h * h + 0.25f;
    real x = fmax(ax, az) - 0.5f, z = fmin(ax, az) - 0.5f;
    real qx = z, qy = h * y - 0.5f * x, qz = h * x + 0.5f * y;
    real s = fmax(-qx, K(0.0f));
    real t = clamp((qy - 0.5f * z) / (m2 + 0.25f), K(0.0f), K(1.0f));
    real a = m2 * (qx + s) * (qx + s) + qy * qy;
    real b = m2 * (qx + 0.5f * t) * (qx + 0.5f * t) + (qy - m2 * t) * (qy - m2 * t);
    real d2 = SEL(fmin(a, b), (real)0.0f, fmin(qy, -qx * m2 - qy * 0.5f) > 0.0f);
    real d = sqrt((d2 + qz * qz) / m2);
    d = fmax(SEL(d, -d, fmax(qz, -y) < 0.0f), -y);
    real sx = fmax(ax - 0.5f, K(0.0f)), sz = fmax(az - 0.5f, K(0.0f));
    real below = sqrt(sx * sx + sz * sz + y * y);
    // On the base plane too (y == 0): the slope formula's sign is 0 there.
    return SEL(d, below, y <= 0.0f) * base;
}

//! fn sd_triangle
//! deps: shape_helpers
//! class: exact
// A triangle a, b, c thickened to a slab of half thickness `half`: the
// exact unsigned distance to the triangle minus half.
inline real sd_triangle(vec3 p, vec3 a, vec3 b, vec3 c, real thick)
{
    vec3 ba = v3_sub(b, a), pa = v3_sub(p, a);
    vec3 cb = v3_sub(c, b), pb = v3_sub(p, b);
    vec3 ac = v3_sub(a, c), pc = v3_sub(p, c);
    vec3 nor = v3_cross(ba, ac);
    real sides = sign(v3_dot(v3_cross(ba, nor), pa)) + sign(v3_dot(v3_cross(cb, nor), pb)) +
                 sign(v3_dot(v3_cross(ac, nor), pc));
    real edge = fmin(fmin(sd_segment2(ba, pa), sd_segment2(cb, pb)), sd_segment2(ac, pc));
    real np = v3_dot(nor, pa);
    real face = np * np / v3_dot2(nor);
    return sqrt(SEL(face, edge, sides < 2.0f)) - thick;
}

//! fn sd_quad
//! deps: shape_helpers
//! class: exact
// A planar convex quad a, b, c, d thickened to half thickness `half`.
inline real sd_quad(vec3 p, vec3 a, vec3 b, vec3 c, vec3 d, real thick)
{
    vec3 ba = v3_sub(b, a), pa = v3_sub(p, a);
    vec3 cb = v3_sub(c, b), pb = v3_sub(p, b);
    vec3 dc = v3_sub(d, c), pc = v3_sub(p, c);
    vec3 ad = v3_sub(a, d), pd = v3_sub(p, d);
    vec3 nor = v3_cross(ba, ad);
    real sides = sign(v3_dot(v3_cross(ba, nor), pa)) + sign(v3_dot(v3_cross(cb, nor), pb)) +
                 sign(v3_dot(v3_cross(dc, nor), pc)) + sign(v3_dot(v3_cross(ad, nor), pd));
    real edge = fmin(fmin(sd_segment2(ba, pa), sd_segment2(cb, pb)), fmin(sd_segment2(dc, pc), sd_segment2(ad, pd)));
    real np = v3_dot(nor, pa);
    real face = np * np / v3_dot2(nor);
    return sqrt(SEL(face, edge, sides < 3.0f)) - thick;
}

//! fn sd_box_frame
//! deps: vec3_ops
//! class: exact
// The edges of a box with half extents h, as square bars of width e.
inline real sd_box_frame(vec3 p, vec3 h, real e)
{
    vec3 a = v3_sub(v3_abs(p), h);
    vec3 q = v3_sub(v3_abs(v3_add(a, v3_splat(e))), v3_splat(e));
    real d1 = v3_length(v3_max_s(v3(a.x, q.y, q.z), K(0.0f))) + fmin(fmax(a.x, fmax(q.y, q.z)), K(0.0f));
    real d2 = v3_length(v3_max_s(v3(q.x, a.y, q.z), K(0.0f))) + fmin(fmax(q.x, fmax(a.y, q.z)), K(0.0f));
    real d3 = v3_length(v3_max_s(v3(q.x, q.y, a.z), K(0.0f))) + fmin(fmax(q.x, fmax(q.y, a.z)), K(0.0f));
    return fmin(fmin(d1, d2), d3);
}

//! fn sd_solid_angle
//! deps: vec3_ops
//! class: exact
// The part of a ball of radius ra inside the cone of half-angle a about +z,
// apex at the centre; s, c = sin a, cos a (Quilez's sdSolidAngle, z up).
inline real sd_solid_angle(vec3 p, real s, real c, real ra)
{
    real qx = sqrt(p.x * p.x + p.y * p.y), qy = p.z;
    real l = sqrt(qx * qx + qy * qy) - ra;
    real t = fmin(fmax(qx * s + qy * c, K(0.0f)), ra);
    real mx = qx - s * t, my = qy - c * t;
    return fmax(l, sqrt(mx * mx + my * my) * sign(c * qx - s * qy));
}
