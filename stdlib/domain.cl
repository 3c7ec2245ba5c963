//! fn dm_axis_helpers
//! deps: vec3_ops
//! class: helper
// Operations along an axis (0 = x, 1 = y, 2 = z; a compile-time constant,
// so the branches fold): the point with `axis` moved to z, and back.
inline vec3 dm_to_z(vec3 p, int axis)
{
    return axis == 0 ? v3(p.y, p.z, p.x) : axis == 1 ? v3(p.z, p.x, p.y) : p;
}
inline vec3 dm_from_z(vec3 q, int axis)
{
    return axis == 0 ? v3(q.z, q.x, q.y) : axis == 1 ? v3(q.y, q.z, q.x) : q;
}
// Distance from p to the box [lo, hi] (0 inside): a lower bound of the
// distance to anything inside the box.
inline real dm_box_outside(vec3 p, vec3 lo, vec3 hi)
{
    vec3 c = v3(fmax(lo.x - p.x, p.x - hi.x), fmax(lo.y - p.y, p.y - hi.y), fmax(lo.z - p.z, p.z - hi.z));
    return v3_length(v3_max_s(c, K(0.0f)));
}

//! fn dm_repeat_axis
//! class: helper
// One axis of a repetition with period s and n copies (n = 0: endless),
// centred on 0. Returns the coordinate in the point's own cell; *near gets
// the coordinate in the neighbouring cell the child may reach across from
// (for a finite row at its end, the one inside the row).
inline real dm_repeat_axis(real x, real s, real n, real* near)
{
    real mid = SEL((real)0.0f, 0.5f * (n - 1.0f), n > 0.0f);  // endless rows are centred on a cell
    real i = round(x / s + mid);
    i = SEL(i, fmin(fmax(i, K(0.0f)), n - 1.0f), n > 0.0f);
    real u = x - s * (i - mid);
    real side = SEL((real)1.0f, (real)-1.0f, u < 0.0f);
    mask outside = (n > 0.0f) & ((i + side < 0.0f) | (i + side > n - 1.0f));
    side = SEL(side, -side, outside);
    side = SEL(side, (real)0.0f, n == 1.0f);
    *near = x - s * (i + side - mid);
    return u;
}

//! fn dm_twist
//! deps: dm_axis_helpers
//! class: helper
// Twist about `axis` by `rate` radians per unit along it: the point is
// turned back by the angle at its height.
inline vec3 dm_twist(vec3 p, int axis, real rate)
{
    vec3 q = dm_to_z(p, axis);
    real a = -rate * q.z, c = cos(a), s = sin(a);
    return dm_from_z(v3(c * q.x - s * q.y, s * q.x + c * q.y, q.z), axis);
}

//! fn dm_bend
//! deps: dm_axis_helpers
//! class: helper
// Bend a bar lying along `axis` towards the next axis (x towards y, y
// towards z, z towards x): the cross-section at coordinate t along the axis
// turns by rate * t in that plane.
inline vec3 dm_bend(vec3 p, int axis, real rate)
{
    // In z-first order (axis -> z), the bar's plane is (z, x).
    vec3 q = dm_to_z(p, axis);
    real a = rate * q.z, c = cos(a), s = sin(a);
    return dm_from_z(v3(s * q.z + c * q.x, q.y, c * q.z - s * q.x), axis);
}

//! fn dm_polar
//! deps: dm_axis_helpers
//! class: helper
// Polar repetition about `axis`: `count` sectors. Returns the point turned
// into its own sector; *near gets it turned into the neighbouring sector on
// its side.
inline vec3 dm_polar(vec3 p, int axis, real count, vec3* near)
{
    vec3 q = dm_to_z(p, axis);
    real sector = 2.0f * acos(K(-1.0f)) / count;  // 2 pi in the kernel's precision
    real a = atan2(q.y, q.x);
    real i = round(a / sector);
    real u = a - i * sector;
    real j = i + SEL((real)1.0f, (real)-1.0f, u < 0.0f);
    real r = sqrt(q.x * q.x + q.y * q.y);
    real a0 = a - i * sector, a1 = a - j * sector;
    *near = dm_from_z(v3(r * cos(a1), r * sin(a1), q.z), axis);
    return dm_from_z(v3(r * cos(a0), r * sin(a0), q.z), axis);
}

//! fn dm_symmetry_octahedral
//! deps: vec3_ops
//! class: helper
// Folds space into one of the 48 chambers of the cube's symmetry group:
// abs on every axis, then sort so x >= y >= z (reflections: distances keep L).
inline vec3 dm_symmetry_octahedral(vec3 p)
{
    p = v3_abs(p);
    real a = fmax(p.x, p.y), b = fmin(p.x, p.y);
    real x = fmax(a, p.z), c = fmin(a, p.z);
    return v3(x, fmax(b, c), fmin(b, c));
}

//! fn dm_symmetry_tetrahedral
//! deps: vec3_ops
//! class: helper
// Folds by the reflections of the regular tetrahedron's group (planes
// x = -y, x = -z, y = -z; seed 001 part III's "tetrahedral fold").
inline vec3 dm_symmetry_tetrahedral(vec3 p)
{
    mask m = p.x + p.y < 0.0f;
    real x = SEL(p.x, -p.y, m), y = SEL(p.y, -p.x, m);
    m = x + p.z < 0.0f;
    real z = SEL(p.z, -x, m);
    x = SEL(x, -p.z, m);
    m = y + z < 0.0f;
    real y2 = SEL(y, -z, m);
    z = SEL(z, -y, m);
    return v3(x, y2, z);
}
