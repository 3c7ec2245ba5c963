//! fn os_item
//! deps: vec3_ops, sd_sphere, sd_box, op_blend_polynomial
//! class: bound
// One item of an object set (see the compiler's ir/object_set.hpp for the
// layout): a sphere or box record, or several smooth-united in order, the
// same operations the unrolled union would do. In packets always inlined:
// a call copies the packet's point (768 bytes at 64 lanes) onto the stack,
// about a sixth of the list march's time at 10 000 objects. One lane gains
// nothing by it and ran 4 % slower.
#if SDFC_WIDTH == 1
#define OS_ITEM_INLINE inline
#else
#define OS_ITEM_INLINE inline __attribute__((always_inline))
#endif
inline real os_prim(vec3 p, __global const float* r)
{
    vec3 q = v3_sub(p, v3((real)r[1], (real)r[2], (real)r[3]));
    if (r[0] == 0.0f) return sd_sphere(q, (real)r[4]);
    return sd_box(q, v3((real)r[4], (real)r[5], (real)r[6]), (real)r[7]);
}
OS_ITEM_INLINE real os_item(vec3 p, __global const float* item, __global const float* prims)
{
    __global const float* r = prims + 8 * (int)item[0];
    const int count = (int)item[1];
    real d = os_prim(p, r);
    for (int k = 1; k < count; ++k) d = op_blend_polynomial(d, os_prim(p, r + 8 * k), (real)item[2]);
    return d;
}

//! fn os_cone
//! deps: vec3_ops, lanes_minmax
//! class: helper
// The cone from the camera that holds a packet's camera rays and the hit
// band around each: an object set's items outside it can neither stop those
// rays nor come within the hit band of them, so the camera march walks only
// the boxes that reach into it (os_in_cone) and steps by the distance to
// those items. The steps are longer than the whole set's distance allows,
// but still safe: a step stays inside the ray's ball free of the items in
// the cone, and inside the cone, which holds none of the others.
struct os_list;
typedef struct
{
    scalar ox, oy, oz;    // apex: the camera
    scalar ax, ay, az;    // unit axis
    scalar cos_a, sin_a;  // half-angle, margin included
    scalar margin;        // the margin: twice the hit band's angle
    scalar cos_w, sin_w;  // the list's cone (os_list): wider by the reach of the hits' shading
    int on;               // 0: no cone (every other ray): the whole set counts
    int shade;            // 1: shading the hits from the list (os_union_shade), else the camera march
    struct os_list* list; // the set's items in the cone (os_list), or 0: walk the hierarchy
} os_cone;

inline os_cone os_cone_none(void)
{
    os_cone c = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0, 0, 0};
    return c;
}

// How far the point (x, y, z) lies from the cone's axis, and `along` it.
inline scalar os_axis_perp(const os_cone c, scalar x, scalar y, scalar z, scalar* along)
{
    const scalar vx = x - c.ox, vy = y - c.oy, vz = z - c.oz;
    *along = vx * c.ax + vy * c.ay + vz * c.az;
    const scalar wx = vx - *along * c.ax, wy = vy - *along * c.ay, wz = vz - *along * c.az;
    return sqrt(wx * wx + wy * wy + wz * wz);
}

// Whether the ball of radius r about (x, y, z) may reach into the camera
// rays' cone (half-angle a). perp cos a - along sin a is at most 0 inside
// the cone and changes no faster than the point moves, so where it exceeds
// r at the centre, the whole ball is outside. (os_list_gather tests the
// list's wider cone, cos_w and sin_w, the same way.)
inline bool os_ball_in_cone(const os_cone c, scalar x, scalar y, scalar z, scalar r)
{
    scalar along;
    return os_axis_perp(c, x, y, z, &along) * c.cos_a - along * c.sin_a <= r;
}

// Whether the box (lo xyz, hi xyz) may reach into the cone: its ball may.
inline bool os_in_cone(const os_cone c, __global const float* b)
{
    if (!c.on) return true;
    const scalar hx = 0.5f * (b[3] - b[0]), hy = 0.5f * (b[4] - b[1]), hz = 0.5f * (b[5] - b[2]);
    return os_ball_in_cone(c, b[0] + hx, b[1] + hy, b[2] + hz, sqrt(hx * hx + hy * hy + hz * hz));
}

// The radius of a sphere or box record's bounding ball about its centre.
inline scalar os_prim_radius(__global const float* r)
{
    return r[0] == 0.0f ? (scalar)r[4] : sqrt((scalar)(r[4] * r[4] + r[5] * r[5] + r[6] * r[6]));
}

// How far an item's smooth blend reaches below its primitives' minimum: a
// quarter of its radius for each blend in its chain (one blend may lower
// the minimum by k/4, and the next blends from there), 0 for one primitive.
// Its primitives' balls grown by this hold its surface and hit band.
inline scalar os_item_reach(__global const float* item)
{
    return (scalar)((int)item[1] - 1) * 0.25f * item[2];
}

// Whether an item may reach into the cone: some primitive's ball, grown by
// the item's reach (os_item_reach), may.
inline bool os_item_in_cone(const os_cone c, __global const float* item, __global const float* prims)
{
    if (!c.on) return true;
    __global const float* r = prims + 8 * (int)item[0];
    const int count = (int)item[1];
    if (count == 1) return os_ball_in_cone(c, r[1], r[2], r[3], os_prim_radius(r));
    const scalar reach = os_item_reach(item);
    for (int k = 0; k < count; ++k, r += 8)
        if (os_ball_in_cone(c, r[1], r[2], r[3], os_prim_radius(r) + reach)) return true;
    return false;
}

//! fn os_union
//! deps: vec3_ops, os_item, os_cone, os_union_list, os_union_shade
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
// With a cone (os_cone: camera rays) only the boxes reaching into it count.
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
__attribute__((noinline)) real os_union_walk(vec3 p, __global const float* s, const int n_nodes, const int n_items,
                                              const real bound, const mask live, const os_cone cone, real* mat)
{
    __global const float* items = s + 8 * n_nodes;
    __global const float* prims = items + 4 * n_items;
    real best = bound, m = (real)(0.0f);
    int stack[OS_STACK];
    real box[OS_STACK];
    int top = 0;
    if (os_in_cone(cone, s)) {
        stack[top] = 0;
        box[top++] = os_box_sq(p, s);
    }
    while (top > 0) {
        --top;
        if (!M_ANY(live & (box[top] < best * fabs(best)))) continue;
        const int node = stack[top];
        __global const float* b = s + 8 * node;
        const int first = (int)b[6], count = (int)b[7];
        if (count > 0) {
            for (int i = first; i < first + count; ++i) {
                if (!os_item_in_cone(cone, items + 4 * i, prims)) continue;
                real d = os_item(p, items + 4 * i, prims);
                m = SEL(m, (real)items[4 * i + 3], d < best);
                best = fmin(best, d);
            }
        } else {
            const int left = node + 1;
            const real best_sq = best * fabs(best);
            real dl = best_sq, dr = best_sq;
            bool need_l = false, need_r = false;
            if (os_in_cone(cone, s + 8 * left)) {
                dl = os_box_sq(p, s + 8 * left);
                need_l = M_ANY(live & (dl < best_sq));
            }
            if (os_in_cone(cone, s + 8 * first)) {
                dr = os_box_sq(p, s + 8 * first);
                need_r = M_ANY(live & (dr < best_sq));
            }
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

// The camera march reads the packet's list (os_union_list) and the hits'
// shading reads it where it answers (os_union_shade); the rest walks. The
// choice is inlined where the scene calls the set and the walk is not: a
// walk inlined into the march made every step set up its stacks (flat
// 10 000 at 64 lanes: 28 ms against 24.6).
inline __attribute__((always_inline)) real os_union(vec3 p, __global const float* s, const int n_nodes,
                                                    const int n_items, const real bound, const mask live,
                                                    const os_cone cone, real* mat)
{
    if (cone.list != 0 && cone.list->n >= 0) {
        __global const float* items = s + 8 * n_nodes;
        __global const float* prims = items + 4 * n_items;
        if (!cone.shade) return os_union_list(p, items, prims, bound, live, cone, mat);
        real d;
        if (os_union_shade(p, items, prims, bound, live, cone, &d, mat)) return d;
    }
    return os_union_walk(p, s, n_nodes, n_items, bound, live, cone, mat);
}

//! fn os_camera_cone
//! deps: os_cone
//! class: helper
// The cone of the rays from ro (one point for every lane: a pinhole camera)
// along the unit directions rd, widened by twice `band` radians (the hit
// band's angle: hit epsilon times the pixel angle), so rounding cannot
// shave the band. A cone wider than about 78 degrees would cull little: none.
// The list's cone (os_list) is wider by twice `reach` radians: the angle of
// the farthest normal tap from its hit, so that the hits are shaded from
// the list (os_union_shade) even at the packet's edge. Not widened, the
// list does not shade (os_cone_shading).
inline os_cone os_camera_cone(vec3 ro, vec3 rd, real band, real reach)
{
    os_cone c;
    c.ox = LANES_MIN(ro.x);
    c.oy = LANES_MIN(ro.y);
    c.oz = LANES_MIN(ro.z);
    const scalar ax = LANES_MIN(rd.x) + LANES_MAX(rd.x), ay = LANES_MIN(rd.y) + LANES_MAX(rd.y),
                 az = LANES_MIN(rd.z) + LANES_MAX(rd.z);
    const scalar len = sqrt(ax * ax + ay * ay + az * az);
    c.ax = ax / len;
    c.ay = ay / len;
    c.az = az / len;
    const scalar cos_t = fmin(LANES_MIN(rd.x * c.ax + rd.y * c.ay + rd.z * c.az), K(1.0f));
    const scalar sin_t = sqrt(fmax(K(1.0f) - cos_t * cos_t, K(0.0f)));
    const scalar m = 2.0f * LANES_MAX(band);
    const scalar cos_m = cos(m), sin_m = sin(m);
    c.cos_a = cos_t * cos_m - sin_t * sin_m;
    c.sin_a = sin_t * cos_m + cos_t * sin_m;
    c.margin = m;
    c.on = len > 0.0f && c.cos_a > 0.2f;
    // Widened only where that less than doubles the rays' own angle: around
    // one lane's pixel the taps' reach would list several times the items.
    const scalar w = 2.0f * LANES_MAX(reach), cos_r = cos(w), sin_r = sin(w);
    c.cos_w = c.cos_a * cos_r - c.sin_a * sin_r;
    c.sin_w = c.sin_a * cos_r + c.cos_a * sin_r;
    if (w == 0.0f || w > sin_t || c.cos_w <= 0.2f) c.cos_w = c.cos_a, c.sin_w = c.sin_a;
    c.shade = 0;
    c.list = 0;
    return c;
}

//! fn march_sphere_trace_cone
//! deps: vec3_ops, os_cone, march_advance
//! after-scene
//! class: helper
// march_sphere_trace for camera rays in a scene with object sets: the
// distance counts only the items that reach into the packet's cone
// (os_cone), so a ray passing small objects beside its path steps past
// them. It hits what the full distance would: an item outside the cone is
// farther from every point of the rays than the hit band.
inline mask march_sphere_trace_cone(TIME_PARAM vec3 ro, vec3 rd, real t0, real t1, mask active,
                                    real pixel_angle, real hit_eps, real step_factor,
                                    int max_steps, real* t_out, real* steps, const os_cone cone)
{
    real t = t0;
    mask hit = active & !active;
    real n = 0.0f;
    for (int i = 0; i < max_steps && M_ANY(active); ++i) {
        real d = scene_dist_cone(TIME_ARG v3_mad(ro, rd, t), active, cone);
        march_advance(d, t1, pixel_angle, hit_eps, step_factor, &t, &active, &hit, &n);
    }
    *t_out = t;
    *steps = n;
    return hit;
}
