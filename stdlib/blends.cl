//! fn op_blend_polynomial
//! class: bound
// Polynomial smooth minimum (Quilez): blends within k; never above
// min(a, b), Lipschitz <= 1. Smooth intersections and differences are
// -op_blend_polynomial(-a, -b, k) and -op_blend_polynomial(-a, b, k).
inline real op_blend_polynomial(real a, real b, real k)
{
    real h = fmax(k - fabs(a - b), K(0.0f)) / k;
    return fmin(a, b) - h * h * k * 0.25f;
}

//! fn op_blend_cubic
//! class: bound
// Cubic polynomial smooth minimum (Quilez): C2-smooth, blends within k;
// never above min(a, b), Lipschitz <= 1.
inline real op_blend_cubic(real a, real b, real k)
{
    real h = fmax(k - fabs(a - b), K(0.0f)) / k;
    return fmin(a, b) - h * h * h * k * (K(1.0f) / K(6.0f));  // 1/6 in the kernel's precision
}

//! fn op_blend_exponential
//! class: bound
// Exponential smooth minimum -k log2(2^(-a/k) + 2^(-b/k)), written around
// min(a, b) so it neither overflows nor underflows far from the surface.
inline real op_blend_exponential(real a, real b, real k)
{
    real m = fmin(a, b);
    return m - k * log2(exp2((m - a) / k) + exp2((m - b) / k));
}

//! fn op_blend_chamfer
//! class: bound
// hg_sdf fOpUnionChamfer: a 45-degree chamfer of size r. Its Lipschitz
// constant reaches sqrt(2) where the two gradients agree.
inline real op_blend_chamfer(real a, real b, real r)
{
    return fmin(fmin(a, b), (a - r + b) * sqrt(K(0.5f)));
}

//! fn op_blend_round
//! class: bound
// hg_sdf fOpUnionRound: a quarter-circle fillet of radius r (L <= sqrt(2)).
inline real op_blend_round(real a, real b, real r)
{
    real ua = fmax(r - a, K(0.0f)), ub = fmax(r - b, K(0.0f));
    return fmax(r, fmin(a, b)) - sqrt(ua * ua + ub * ub);
}

//! fn op_blend_columns
//! class: bound
// hg_sdf fOpUnionColumns: n round columns along the seam (L <= sqrt(2)).
// hg_sdf switches the columns on where a < r and b < r, which leaves a jump
// in the field at that border (the march can skip a column's edge); here
// the columns are cut by that region with a max instead, so the field is
// continuous and the surface the same.
inline real op_blend_columns(real a, real b, real r, real n)
{
    real column = r * sqrt(K(2.0f)) / ((n - 1.0f) * 2.0f + sqrt(K(2.0f)));
    real px = (a + b) * sqrt(K(0.5f)), py = (b - a) * sqrt(K(0.5f));
    px += -sqrt(K(0.5f)) * r + column * sqrt(K(2.0f));
    py += SEL((real)0.0f, column, fmod(n, K(2.0f)) == 1.0f);
    real size = 2.0f * column;
    py = py + 0.5f * size;
    py = py - size * floor(py / size) - 0.5f * size;
    real cols = fmin(sqrt(px * px + py * py) - column, px);
    return fmin(fmin(a, b), fmax(cols, fmax(a, b) - r));
}

//! fn op_blend_stairs
//! class: bound
// hg_sdf fOpUnionStairs: n steps of total size r along the seam (L <= 1).
inline real op_blend_stairs(real a, real b, real r, real n)
{
    real s = r / n, u = b - r;
    real w = u - a + s, m = 2.0f * s;
    real md = w - m * floor(w / m);
    return fmin(fmin(a, b), 0.5f * (u + a + fabs(md - s)));
}
