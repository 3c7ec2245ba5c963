//! fn mat_record
//! deps: vec3_ops
//! class: helper
// A material's shading parameters as one value, so a smooth blend can mix
// two of them. Only kernels with a smooth blend of differing
// materials carry it; the others keep a material id.
typedef struct
{
    vec3 albedo;
    real specular, shininess, reflectivity;
} mat_record;

inline mat_record mat_none(void)
{
    mat_record r;
    r.albedo = v3_splat(0.0f);
    r.specular = r.shininess = r.reflectivity = (real)(0.0f);
    return r;
}

inline mat_record mat_select(mat_record a, mat_record b, mask m)
{
    mat_record r;
    r.albedo = v3_select(a.albedo, b.albedo, m);
    r.specular = SEL(a.specular, b.specular, m);
    r.shininess = SEL(a.shininess, b.shininess, m);
    r.reflectivity = SEL(a.reflectivity, b.reflectivity, m);
    return r;
}

// a where w = 0, b where w = 1, linear between.
inline mat_record mat_mix(mat_record a, mat_record b, real w)
{
    mat_record r;
    r.albedo = v3_mix(a.albedo, b.albedo, w);
    r.specular = mix(a.specular, b.specular, w);
    r.shininess = mix(a.shininess, b.shininess, w);
    r.reflectivity = mix(a.reflectivity, b.reflectivity, w);
    return r;
}

//! fn op_weight_polynomial
//! class: helper
// The share of b in op_blend_polynomial(a, b, k): the derivative of the blend
// with respect to b, so the two shares sum to 1 and weight each child as
// much as it shapes the surface; 1/2 where a = b, 0 once b >= a + k.
inline real op_weight_polynomial(real a, real b, real k)
{
    return clamp(0.5f + 0.5f * (a - b) / k, K(0.0f), K(1.0f));
}

//! fn op_weight_cubic
//! class: helper
// The share of b in op_blend_cubic(a, b, k) (its derivative in b).
inline real op_weight_cubic(real a, real b, real k)
{
    real h = fmax(k - fabs(a - b), K(0.0f)) / k;
    real w = 0.5f * h * h;  // the share of the farther child
    return SEL(w, 1.0f - w, b < a);
}

//! fn op_weight_exponential
//! class: helper
// The share of b in op_blend_exponential(a, b, k) (its derivative in b),
// written around min(a, b) like the blend.
inline real op_weight_exponential(real a, real b, real k)
{
    real m = fmin(a, b);
    real ea = exp2((m - a) / k), eb = exp2((m - b) / k);
    return eb / (ea + eb);
}
