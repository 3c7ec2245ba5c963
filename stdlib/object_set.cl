//! fn os_item
//! deps: vec3_ops, sd_sphere, sd_box, op_blend_polynomial
//! class: bound
// One item of an object set (see the compiler's ir/object_set.hpp for the
// layout): a sphere or box record, or several smooth-united in order, the
// same operations the unrolled union would do.
inline real os_prim(vec3 p, __global const float* r)
{
    vec3 q = v3_sub(p, v3((real)r[1], (real)r[2], (real)r[3]));
    if (r[0] == 0.0f) return sd_sphere(q, (real)r[4]);
    return sd_box(q, v3((real)r[4], (real)r[5], (real)r[6]), (real)r[7]);
}
inline real os_item(vec3 p, __global const float* item, __global const float* prims)
{
    __global const float* r = prims + 8 * (int)item[0];
    const int count = (int)item[1];
    real d = os_prim(p, r);
    for (int k = 1; k < count; ++k) d = op_blend_polynomial(d, os_prim(p, r + 8 * k), (real)item[2]);
    return d;
}

//! fn os_union
//! deps: vec3_ops, os_item
//! class: bound
// The nearest item of an object set, and its material: a walk of the
// bounding-volume hierarchy that skips a node while every lane's nearest
// item so far is nearer than the node's box. The box's signed distance is a
// lower bound of every item inside it (the host grows each box by how far
// its smooth blend reaches), so the result is the exact minimum over all
// items, as the unrolled union's. `bound` is the distance of the union's
// other children: items no nearer cannot change the union, so the walk
// starts with it as the nearest so far (and returns it where no item is
// nearer, leaving `mat` 0 there). A child is pushed only if some lane needs
// it, and of two the one nearest to any lane is visited first: in a packet
// the lanes sit by different items, and the lane nearest to a box is the one
// most likely to find its nearest item there. Each box is measured once: its
// measure (os_box_sq) waits on the stack beside it.
// Only `live` lanes open boxes: in a marching loop the lanes that have
// stopped still evaluate, but their values are thrown away, and a stopped
// lane sits on a surface, where its path down the hierarchy is its own.
#define OS_STACK 64
// The box's signed distance times its magnitude: it orders as the distance
// does without a square root, so the walk compares it with best * |best|.
inline real os_box_sq(vec3 p, __global const float* b)
{
    vec3 q = v3(fmax((real)b[0] - p.x, p.x - (real)b[3]), fmax((real)b[1] - p.y, p.y - (real)b[4]),
                fmax((real)b[2] - p.z, p.z - (real)b[5]));
    vec3 outside = v3_max_s(q, K(0.0f));
    real inside = fmin(v3_max_comp(q), K(0.0f));
    return v3_dot(outside, outside) - inside * inside;
}
// The smallest of the live lanes' values, to choose which child to visit
// first. Taken on the floats' bits as integers, which order as the floats
// do where both are positive, and cheaply: a float minimum must also handle
// NaN, and made the walk slower at 16 lanes than the choice saved. Negative
// values (a lane inside the box) come first either way.
#if SDFC_WIDTH == 1
#define OS_NEAREST(d, live) (d)
#else
#define OS_NEAREST(d, live) __builtin_reduce_min(__builtin_astype(SEL(K(1e30f), (d), (live)), mask))
#endif
inline real os_union(vec3 p, __global const float* s, const int n_nodes, const int n_items, const real bound,
                     const mask live, real* mat)
{
    __global const float* items = s + 8 * n_nodes;
    __global const float* prims = items + 4 * n_items;
    real best = bound, m = (real)(0.0f);
    int stack[OS_STACK];
    real box[OS_STACK];
    int top = 0;
    stack[top] = 0;
    box[top++] = os_box_sq(p, s);
    while (top > 0) {
        --top;
        if (!M_ANY(live & (box[top] < best * fabs(best)))) continue;
        const int node = stack[top];
        __global const float* b = s + 8 * node;
        const int first = (int)b[6], count = (int)b[7];
        if (count > 0) {
            for (int i = first; i < first + count; ++i) {
                real d = os_item(p, items + 4 * i, prims);
                m = SEL(m, (real)items[4 * i + 3], d < best);
                best = fmin(best, d);
            }
        } else {
            const int left = node + 1;
            const real dl = os_box_sq(p, s + 8 * left), dr = os_box_sq(p, s + 8 * first);
            const real best_sq = best * fabs(best);
            const bool need_l = M_ANY(live & (dl < best_sq)), need_r = M_ANY(live & (dr < best_sq));
            if (need_l && need_r) {
                const bool left_near = OS_NEAREST(dl, live) < OS_NEAREST(dr, live);
                stack[top] = left_near ? first : left;  // the far child waits below the near one
                box[top++] = left_near ? dr : dl;
                stack[top] = left_near ? left : first;
                box[top++] = left_near ? dl : dr;
            } else if (need_l || need_r) {
                stack[top] = need_l ? left : first;
                box[top++] = need_l ? dl : dr;
            }
        }
    }
    *mat = m;
    return best;
}
