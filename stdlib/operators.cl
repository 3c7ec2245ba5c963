//! fn op_smooth_union
//! class: bound
// Polynomial smooth minimum (Quilez); blends within distance k. Result is a
// bound: it never exceeds min(a, b), and its Lipschitz constant stays <= 1.
inline real op_smooth_union(real a, real b, real k)
{
    real h = fmax(k - fabs(a - b), K(0.0f)) / k;
    return fmin(a, b) - h * h * k * 0.25f;
}

//! fn op_smooth_intersection
//! class: bound
inline real op_smooth_intersection(real a, real b, real k)
{
    real h = fmax(k - fabs(a - b), K(0.0f)) / k;
    return fmax(a, b) + h * h * k * 0.25f;
}

//! fn op_smooth_difference
//! deps: op_smooth_intersection
//! class: bound
// a minus b, smoothed.
inline real op_smooth_difference(real a, real b, real k) { return op_smooth_intersection(a, -b, k); }
