//! fn fold_polyhedral_centre
//! deps: vec3_ops
//! class: helper
// Mandelbulber's generalized box fold, lane by lane: the point of the
// polyhedron (faces dot(x, n_i) = 1, n_i = nv[3i..3i+2], scalars so the
// table stays small) that z is reflected through.
// *kind: 0 inside (no fold), 1 a face (*v its normal), 2 an edge (*v the
// unit direction of its line), 3 a corner. Each search takes the nearest
// face plane crossed by a segment y + a l, 0 < a < 1, as Mandelbulber's does.
inline __attribute__((always_inline)) vec3 fold_polyhedral_centre(vec3 z, const scalar* nv, int sides, real* kind, vec3* v)
{
    const real solid = 1.0f;
    // the face: the first plane the segment from the origin to z crosses
    // a = an / ad (ad > 0) keeps the divisions out of the searches
    real an = 1.0f, ad = 1.0f, m = -1.0f;
    vec3 nm = v3_splat(0.0f);
    #pragma unroll
    for (int i = 0; i < sides; ++i) {
        vec3 n = v3((real)(nv[3 * i]), (real)(nv[3 * i + 1]), (real)(nv[3 * i + 2]));
        real c = v3_dot(z, n);
        mask take = (c > 0.0f) & (an * c > solid * ad);
        an = SEL(an, solid, take);
        ad = SEL(ad, c, take);
        m = SEL(m, (real)(i), take);
        nm = v3_select(nm, n, take);
    }
    vec3 xm = v3_mad(z, nm, -(v3_dot(z, nm) - solid));
    // the edge: a second plane crossed from the face's normal to xm
    vec3 l = v3_sub(xm, nm);
    real r = -1.0f;
    vec3 nr = nm;
    an = 1.0f, ad = 1.0f;
    #pragma unroll
    for (int i = 0; i < sides; ++i) {
        vec3 n = v3((real)(nv[3 * i]), (real)(nv[3 * i + 1]), (real)(nv[3 * i + 2]));
        real b = solid - v3_dot(nm, n), c = v3_dot(l, n);
        mask take = ((real)(i) != m) & (c > 0.0f) & (an * c > b * ad);
        an = SEL(an, b, take);
        ad = SEL(ad, c, take);
        r = SEL(r, (real)(i), take);
        nr = v3_select(nr, n, take);
    }
    vec3 xmr = v3_mad(nm, l, an / ad);
    vec3 lr = v3(nm.y * nr.z - nm.z * nr.y, nm.z * nr.x - nm.x * nr.z, nm.x * nr.y - nm.y * nr.x);
    real ll = fmax(v3_dot(lr, lr), K(1e-30f));
    vec3 xr = v3_mad(xmr, lr, (v3_dot(z, lr) - v3_dot(xmr, lr)) / ll);
    // the corner: a third plane crossed along the edge from xmr to xr
    vec3 l3 = v3_sub(xr, xmr);
    real q = -1.0f;
    an = 1.0f, ad = 1.0f;
    #pragma unroll
    for (int i = 0; i < sides; ++i) {
        vec3 n = v3((real)(nv[3 * i]), (real)(nv[3 * i + 1]), (real)(nv[3 * i + 2]));
        real b = solid - v3_dot(xmr, n), c = v3_dot(l3, n);
        mask take = ((real)(i) != m) & ((real)(i) != r) & (c > 0.0f) & (an * c > b * ad);
        an = SEL(an, b, take);
        ad = SEL(ad, c, take);
        q = SEL(q, (real)(i), take);
    }
    mask face = m >= 0.0f, edge = face & (r >= 0.0f), corner = edge & (q >= 0.0f);
    *kind = SEL(SEL(SEL((real)(0.0f), (real)(1.0f), face), (real)(2.0f), edge), (real)(3.0f), corner);
    *v = v3_select(nm, v3_scale(lr, rsqrt(ll)), edge);
    return v3_select(v3_select(xm, xr, edge), v3_mad(xmr, l3, an / ad), corner);
}

//! fn fold_polyhedral
//! deps: vec3_ops, fold_polyhedral_centre
//! class: helper
// The generalized box fold with the scalar derivative (an isometry: dr kept).
inline __attribute__((always_inline)) vec3 fold_polyhedral(vec3 z, const scalar* nv, int sides)
{
    real kind;
    vec3 v;
    vec3 x = fold_polyhedral_centre(z, nv, sides, &kind, &v);
    return v3_select(z, v3_sub(v3_scale(x, 2.0f), z), kind > 0.5f);
}

//! fn fold_polyhedral_j
//! deps: vec3_ops, fold_polyhedral_centre
//! class: helper
// The generalized box fold on z and the Jacobian's columns: a face
// reflection takes J - 2 n (n.J), an edge turn 2 u (u.J) - J, a corner -J.
inline __attribute__((always_inline)) void fold_polyhedral_j(vec3* z, vec3* ja, vec3* jb, vec3* jc, const scalar* nv, int sides)
{
    real kind;
    vec3 v;
    vec3 x = fold_polyhedral_centre(*z, nv, sides, &kind, &v);
    mask on = kind > 0.5f;
    real sg = SEL((real)(1.0f), (real)(-1.0f), kind > 1.5f);                                      // -J off a face
    real k = SEL(SEL((real)(0.0f), (real)(-2.0f), kind > 0.5f), (real)(2.0f), kind > 1.5f);    // the n or u term
    k = SEL(k, (real)(0.0f), kind > 2.5f);
    *ja = v3_mad(v3_scale(*ja, sg), v, k * v3_dot(*ja, v));
    *jb = v3_mad(v3_scale(*jb, sg), v, k * v3_dot(*jb, v));
    *jc = v3_mad(v3_scale(*jc, sg), v, k * v3_dot(*jc, v));
    *z = v3_select(*z, v3_sub(v3_scale(x, 2.0f), *z), on);
}
