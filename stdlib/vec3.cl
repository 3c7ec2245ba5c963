//! fn vec3_ops
//! class: helper
// Structure-of-arrays 3-vectors over `real`: at width 1 `real` is a scalar,
// at width N it is floatN/doubleN and every helper works lane by lane.
// Literals carry an f suffix (a double literal next to a float vector is an
// error in OpenCL C, a float literal promotes cleanly to double), and those
// passed to builtins are wrapped in K(), the prelude's scalar type, since
// fmax(double, float) is ambiguous.
inline vec3 v3(real x, real y, real z) { vec3 r; r.x = x; r.y = y; r.z = z; return r; }
inline vec3 v3_splat(real s) { return v3(s, s, s); }
inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
inline vec3 v3_scale(vec3 a, real s) { return v3(a.x * s, a.y * s, a.z * s); }
inline vec3 v3_mad(vec3 a, vec3 b, real s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
inline real v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline real v3_length(vec3 a) { return sqrt(v3_dot(a, a)); }
inline vec3 v3_abs(vec3 a) { return v3(fabs(a.x), fabs(a.y), fabs(a.z)); }
inline vec3 v3_max_s(vec3 a, real s) { return v3(fmax(a.x, s), fmax(a.y, s), fmax(a.z, s)); }
inline real v3_max_comp(vec3 a) { return fmax(a.x, fmax(a.y, a.z)); }
inline vec3 v3_normalize(vec3 a) { return v3_scale(a, rsqrt(fmax(v3_dot(a, a), K(1e-30f)))); }
inline vec3 v3_select(vec3 a, vec3 b, mask m) { return v3(SEL(a.x, b.x, m), SEL(a.y, b.y, m), SEL(a.z, b.z, m)); }
inline vec3 v3_mix(vec3 a, vec3 b, real t) { return v3(mix(a.x, b.x, t), mix(a.y, b.y, t), mix(a.z, b.z, t)); }
// Rows of a 3x3 matrix given as nine scalars (row-major), applied to a.
inline vec3 v3_mat(vec3 a, real m00, real m01, real m02, real m10, real m11, real m12,
                   real m20, real m21, real m22)
{
    return v3(m00 * a.x + m01 * a.y + m02 * a.z,
              m10 * a.x + m11 * a.y + m12 * a.z,
              m20 * a.x + m21 * a.y + m22 * a.z);
}
