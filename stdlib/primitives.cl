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
