//! fn path_rand
//! deps: fx_hash, fx_fract
//! class: helper
// A pseudo-random number in [0, 1) for dimension dim of sample sf of the
// pixel whose top-left corner is (px, py): a per-pixel rotation of a
// per-sample value, both from fx_hash. It depends on the absolute pixel and
// the sample only, so tiles, progressive passes and farm regions draw the
// same numbers as a whole render (pseudo-random, not low-discrepancy).
inline real path_rand(real px, real py, scalar sf, scalar dim)
{
    return fx_fract(fx_hash(px, py, (real)(dim + 11.0f)) + fx_hash((real)(sf), (real)(dim), (real)(5.0f)));
}

//! fn path_frame
//! deps: vec3_ops
//! class: exact
// A tangent t and bitangent b with (t, b, n) orthonormal, for a unit n
// (Duff et al. 2017, branchless).
inline void path_frame(vec3 n, vec3* t, vec3* b)
{
    real s = SEL((real)(-1.0f), (real)(1.0f), n.z >= 0.0f);
    real a = -1.0f / (s + n.z);
    real c = n.x * n.y * a;
    *t = v3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    *b = v3(c, s + n.y * n.y * a, -n.y);
}

//! fn path_cosine_dir
//! deps: vec3_ops, path_frame
//! class: exact
// A direction about the unit normal n with density cos(theta) / pi, from
// two uniform numbers (Malley's method: a uniform disc lifted to the
// hemisphere).
inline vec3 path_cosine_dir(vec3 n, real u1, real u2)
{
    vec3 t, b;
    path_frame(n, &t, &b);
    real r = sqrt(u1), phi = 6.28318530718f * u2;
    real z = sqrt(fmax(1.0f - u1, K(0.0f)));
    return v3_normalize(v3_add(v3_scale(n, z), v3_add(v3_scale(t, r * cos(phi)), v3_scale(b, r * sin(phi)))));
}

//! fn path_fresnel
//! deps: vec3_ops
//! class: estimate
// Schlick's approximation of the Fresnel reflectance for a reflectance f0
// at normal incidence and the cosine c between the view and the half vector.
inline vec3 path_fresnel(vec3 f0, real c)
{
    real m = clamp(1.0f - c, K(0.0f), K(1.0f));
    real m5 = m * m * m * m * m;
    return v3_add(f0, v3_scale(v3_sub(v3_splat(1.0f), f0), m5));
}

//! fn path_ggx_g1
//! class: exact
// Smith's masking for the GGX distribution of roughness alpha (exact for
// that microsurface model) at a cosine c to the normal.
inline real path_ggx_g1(real c, real alpha)
{
    real a2 = alpha * alpha;
    return 2.0f * c / (c + sqrt(a2 + (1.0f - a2) * c * c));
}

//! fn path_ggx_half
//! deps: vec3_ops, path_frame
//! class: exact
// A half vector about n drawn from the GGX normal distribution D(h) cos(h):
// tan^2(theta) = alpha^2 u1 / (1 - u1).
inline vec3 path_ggx_half(vec3 n, real alpha, real u1, real u2)
{
    vec3 t, b;
    path_frame(n, &t, &b);
    real c2 = (1.0f - u1) / fmax(1.0f + (alpha * alpha - 1.0f) * u1, K(1e-12f));
    real c = sqrt(clamp(c2, K(0.0f), K(1.0f))), s = sqrt(fmax(1.0f - c2, K(0.0f)));
    real phi = 6.28318530718f * u2;
    return v3_normalize(v3_add(v3_scale(n, c), v3_add(v3_scale(t, s * cos(phi)), v3_scale(b, s * sin(phi)))));
}

//! fn path_glossy_eval
//! deps: vec3_ops, path_fresnel, path_ggx_g1
//! class: exact
// The surface's reflectance towards the light l seen from v, times the
// cosine and pi (so a white diffuse surface facing a light of intensity 1
// returns 1, as the direct integrator's shading does): a diffuse part
// diffuse (1 - F(n.v)) and a GGX lobe D G F / (4 n.v n.l). Exact for that
// model; the model itself loses the light that would scatter several times
// between microfacets, so it never gains energy.
inline vec3 path_glossy_eval(vec3 n, vec3 v, vec3 l, vec3 diffuse, vec3 f0, real alpha)
{
    real nl = v3_dot(n, l), nv = fmax(v3_dot(n, v), K(1e-4f));
    vec3 h = v3_normalize(v3_add(l, v));
    real nh = fmax(v3_dot(n, h), K(0.0f)), vh = fmax(v3_dot(v, h), K(0.0f));
    real a2 = alpha * alpha;
    real q = nh * nh * (a2 - 1.0f) + 1.0f;
    real d = a2 / fmax(q * q, K(1e-12f));  // D(h) times pi
    real g = path_ggx_g1(nv, alpha) * path_ggx_g1(fmax(nl, K(0.0f)), alpha);
    vec3 f = path_fresnel(f0, vh);
    vec3 keep = v3_sub(v3_splat(1.0f), path_fresnel(f0, nv));
    vec3 spec = v3_scale(f, d * g / (4.0f * nv));
    vec3 r = v3_add(v3_scale(v3_mul(diffuse, keep), nl), spec);
    return v3_select(v3_splat(0.0f), r, nl > 0.0f);
}

//! fn path_firefly
//! deps: vec3_ops
//! class: helper
// The firefly clamp: each channel of a contribution limited to c.
inline vec3 path_firefly(vec3 x, real c)
{
    return v3(fmin(x.x, c), fmin(x.y, c), fmin(x.z, c));
}

//! fn path_glossy_pdf
//! deps: vec3_ops
//! class: helper
// The density per solid angle with which a bounce draws l from v: the GGX
// lobe with probability ps (its half vector's density D(h) cos(h) over
// 4 v.h), else the cosine lobe. For weighting an environment map's samples
// against the bounce's (multiple importance sampling).
inline real path_glossy_pdf(vec3 n, vec3 v, vec3 l, real alpha, real ps)
{
    real nl = v3_dot(n, l);
    vec3 h = v3_normalize(v3_add(l, v));
    real nh = fmax(v3_dot(n, h), K(0.0f)), vh = fmax(v3_dot(v, h), K(1e-6f));
    real a2 = alpha * alpha;
    real q = nh * nh * (a2 - 1.0f) + 1.0f;
    real d = a2 / fmax(K(3.14159265359f) * q * q, K(1e-12f));
    real p = ps * d * nh / (4.0f * vh) + (1.0f - ps) * fmax(nl, K(0.0f)) * K(0.31830988618f);
    return SEL(p, (real)(0.0f), nl <= 0.0f);
}
