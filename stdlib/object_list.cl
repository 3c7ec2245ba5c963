//! fn os_list
//! deps: os_cone, os_item
//! class: helper
// The items of an object set in a packet's camera cone, in the order their
// bounding balls begin along the cone's axis: gathered once per packet
// (os_list_gather), so that each step of the camera march measures only the
// items some live lane may still reach (os_union_list) instead of walking
// the hierarchy. A scene with one object set only: the list is that set's.
// The list also holds the items of a wider cone (cos_w), which the hits'
// material and normal taps read (os_union_shade): they lie beside the rays.
// A camera cone holding more items than OS_LIST_CAP keeps the walk (n = -1);
// the wider cone's other items make way for them. 96 holds the wider cone of
// nearly every 8x8 packet in 10 000 scattered objects (64 left 6 % of them
// short, whose hits then walked the set).
#if SDFC_WIDTH == 1
#define OS_LIST_CAP 16
#else
#define OS_LIST_CAP 96
#endif
typedef struct os_list
{
    int n;                                    // items held; -1: too many, walk the hierarchy
    int first;                                // the first not yet behind every live lane
    scalar cos_c, sin_c;                      // the cone whose every item is listed: the wider, or the camera's
    int item[OS_LIST_CAP];                    // the item's index in the set
    scalar lo[OS_LIST_CAP], hi[OS_LIST_CAP];  // where its balls begin and end along the axis
    uchar in_camera[OS_LIST_CAP];             // in the camera rays' cone: the march measures it
} os_list;

// Inserts item i, spanning [lo, hi] along the axis, in order of lo. In a
// full list an item of the camera's cone (`in_camera`) takes the place of the
// last that is only in the wider cone; then, or when that is all the new
// item is, the list holds the camera's cone whole, no longer the wider one.
// False when the camera's cone holds more than the list can.
inline bool os_list_add(os_list* l, const os_cone c, int i, scalar lo, scalar hi, bool in_camera)
{
    if (l->n == OS_LIST_CAP) {
        l->cos_c = c.cos_a;
        l->sin_c = c.sin_a;
        if (!in_camera) return true;
        int k = l->n - 1;
        while (k >= 0 && l->in_camera[k]) --k;
        if (k < 0) return false;
        for (--l->n; k < l->n; ++k) {
            l->item[k] = l->item[k + 1];
            l->lo[k] = l->lo[k + 1];
            l->hi[k] = l->hi[k + 1];
            l->in_camera[k] = l->in_camera[k + 1];
        }
    }
    int k = l->n++;
    for (; k > 0 && l->lo[k - 1] > lo; --k) {
        l->item[k] = l->item[k - 1];
        l->lo[k] = l->lo[k - 1];
        l->hi[k] = l->hi[k - 1];
        l->in_camera[k] = l->in_camera[k - 1];
    }
    l->item[k] = i;
    l->lo[k] = lo;
    l->hi[k] = hi;
    l->in_camera[k] = in_camera;
    return true;
}

// Every item of the set (nodes and items as os_union reads them) that
// reaches into the wider cone, with the span of its balls (os_item_in_cone's:
// each shape's, grown by its blends' reach, os_item_reach) along the axis, and
// whether it reaches into the camera rays' cone, and so do the boxes above
// it (the walk's test, os_union: there every box above; here the boxes of
// every third level, which may let the march measure an item more, never
// one less). The boxes are read from the gather's hierarchy `g`
// (ir/object_set.hpp): the balls about eight boxes at a time, tested
// together, three levels of the walk's hierarchy apart (one at a time the
// tests waited on each other and on the branches between them: a quarter of
// the kernel at 10 000 objects). Leaves come in the walk's order, so the
// list holds the same items in the same order.
#define OS_GATHER_STACK 71
typedef scalar __attribute__((ext_vector_type(8))) os_balls;
typedef scalar __attribute__((ext_vector_type(4))) os_balls4;
inline void os_list_gather(os_list* l, const os_cone c, __global const float* s, const int n_nodes, const int n_items,
                           __global const float* g)
{
    __global const float* items = s + 8 * n_nodes;
    __global const float* prims = items + 4 * n_items;
    const int stride = n_items + 4;                // the items' balls' arrays (ir/object_set.hpp)
    __global const float* balls = g - 4 * stride;  // just before the gather's hierarchy
    l->n = c.on ? 0 : -1;
    l->first = 0;
    l->cos_c = c.cos_w;
    l->sin_c = c.sin_w;
    // 2 ref + 1 where the boxes above reach into the camera rays' cone; ref:
    // a leaf box of the walk's hierarchy, or -1 - a node of the gather's
    int stack[OS_GATHER_STACK];
    int top = 0;
    if (c.on) stack[top++] = -1;  // the gather's root, seen
    while (top > 0) {
        const int e = stack[--top], ref = e >> 1;
        const bool seen = e & 1;
        if (ref < 0) {
            // each ball placed about the axis once, and tested against both cones (os_ball_in_cone's terms)
            __global const float* w = g + 40 * (-1 - ref);
            const os_balls x = __builtin_convertvector(vload8(0, w), os_balls) - c.ox;
            const os_balls y = __builtin_convertvector(vload8(1, w), os_balls) - c.oy;
            const os_balls z = __builtin_convertvector(vload8(2, w), os_balls) - c.oz;
            const os_balls r = __builtin_convertvector(vload8(3, w), os_balls);
            const os_balls along = x * c.ax + y * c.ay + z * c.az;
            const os_balls wx = x - along * c.ax, wy = y - along * c.ay, wz = z - along * c.az;
            const os_balls perp = sqrt(wx * wx + wy * wy + wz * wz);
            const __auto_type camera = perp * c.cos_a - along * c.sin_a <= r;
            const __auto_type wide = perp * c.cos_w - along * c.sin_w <= r;
            for (int k = 7; k >= 0; --k) {  // the first is taken off first
                const bool in_camera = seen && camera[k];
                if (in_camera || wide[k]) stack[top++] = 2 * (int)w[32 + k] + in_camera;
            }
            continue;
        }
        __global const float* b = s + 8 * ref;
        const int first = (int)b[6], count = (int)b[7];
        // the leaf's items' balls first, four at a time (slack for rounding): only the items
        // whose ball reaches into the wider cone are measured shape by shape
        __global const float* ib = balls + first;
        const os_balls4 x = __builtin_convertvector(vload4(0, ib), os_balls4) - c.ox;
        const os_balls4 y = __builtin_convertvector(vload4(0, ib + stride), os_balls4) - c.oy;
        const os_balls4 z = __builtin_convertvector(vload4(0, ib + 2 * stride), os_balls4) - c.oz;
        const os_balls4 r = __builtin_convertvector(vload4(0, ib + 3 * stride), os_balls4);
        const os_balls4 along = x * c.ax + y * c.ay + z * c.az;
        const os_balls4 wx = x - along * c.ax, wy = y - along * c.ay, wz = z - along * c.az;
        const os_balls4 perp = sqrt(wx * wx + wy * wy + wz * wz);
        const __auto_type reaches = perp * c.cos_w - along * c.sin_w <= r + K(1e-5f) * (K(1.0f) + fabs(along) + r);
        for (int i = first; i < first + count; ++i) {
            if (!reaches[i - first]) continue;
            __global const float* item = items + 4 * i;
            __global const float* p = prims + 8 * (int)item[0];
            const scalar reach = os_item_reach(item);
            scalar lo = 1e30f, hi = -1e30f, along;
            bool wide = false, camera = false;
            for (int k = 0; k < (int)item[1]; ++k, p += 8) {
                const scalar radius = os_prim_radius(p) + reach;
                const scalar perp_k = os_axis_perp(c, p[1], p[2], p[3], &along);
                wide = wide || perp_k * c.cos_w - along * c.sin_w <= radius;
                camera = camera || perp_k * c.cos_a - along * c.sin_a <= radius;
                lo = fmin(lo, along - radius);
                hi = fmax(hi, along + radius);
            }
            if (wide && !os_list_add(l, c, i, lo, hi, seen && camera)) {
                l->n = -1;
                return;
            }
        }
    }
}

//! fn os_union_list
//! deps: os_list
//! class: bound
// The live lanes' largest distance so far: no listed item beginning farther
// ahead of every lane than that can lower any of them. It only falls as
// items are measured, so a value taken before is an upper bound of it.
#define OS_WORST(best, live) LANES_MAX(SEL(K(-1e30f), (best), (live)))
// os_union for the camera march from the packet's list: the nearest of the
// listed items some live lane may still reach, and its material. An item
// whose balls end behind every live lane's point (along the axis) by more
// than the hit band is dropped for good: the rays only move forward, and it
// can neither stop them nor come within the band of them. The walk stops at
// the first item beginning farther ahead of every lane than that lane's
// nearest so far: it and all after it are farther still. The distance is
// the listed items' (and `bound`'s), as the cone's walk, less the dropped.
inline real os_union_list(vec3 p, __global const float* items, __global const float* prims, const real bound,
                          const mask live, const os_cone c, real* mat)
{
    os_list* l = c.list;
    const real along = (p.x - c.ox) * c.ax + (p.y - c.oy) * c.ay + (p.z - c.oz) * c.az;
    const scalar nearest = LANES_MIN(SEL(K(1e30f), along, live)), farthest = LANES_MAX(SEL(K(-1e30f), along, live));
    // twice the hit band at the farthest lane (t is at most along / cos a)
    const scalar behind = nearest - c.margin * farthest / c.cos_a;
    while (l->first < l->n && l->hi[l->first] < behind) ++l->first;
    real best = bound, m = (real)(0.0f);
    // the live lanes' largest nearest so far: once an item has lowered it, a
    // stale (larger) value still tells where to stop, and it is taken again
    // only where it would not (OS_WORST)
    scalar worst = OS_WORST(best, live);
    bool stale = false;
    for (int k = l->first; k < l->n; ++k) {
        if (!l->in_camera[k] || l->hi[k] < behind) continue;
        if (stale && l->lo[k] - farthest <= worst) worst = OS_WORST(best, live), stale = false;
        if (l->lo[k] - farthest > worst) break;
        const int i = l->item[k];
        const real d = os_item(p, items + 4 * i, prims);
        m = SEL(m, (real)items[4 * i + 3], d < best);
        best = fmin(best, d);
        stale = true;
    }
    *mat = m;
    return best;
}

//! fn os_union_shade
//! deps: os_list
//! class: bound
// os_union at the hits, from the packet's list (os_cone_shading): the
// nearest of all listed items, the ones the march dropped too, and its
// material. Every item the list leaves out lies outside its cone, so it is
// farther from p than p is deep inside that cone (the cone's perp cos a -
// along sin a changes no faster than the point moves). Where the nearest
// listed item (or `bound`) is no farther than that for every live lane,
// it is the nearest of the whole set: the walk's value, from a few items.
// Elsewhere (a lane near the cone's side, a tap far from its hit) false,
// and os_union walks the hierarchy.
inline bool os_union_shade(vec3 p, __global const float* items, __global const float* prims, const real bound,
                           const mask live, const os_cone c, real* d_out, real* mat)
{
    const os_list* l = c.list;
    const vec3 v = v3(p.x - c.ox, p.y - c.oy, p.z - c.oz);
    const real along = v.x * c.ax + v.y * c.ay + v.z * c.az;
    const vec3 w = v3(v.x - along * c.ax, v.y - along * c.ay, v.z - along * c.az);
    // less a rounding slack: the gather's cone test rounds too
    const real depth = along * l->sin_c - sqrt(v3_dot(w, w)) * l->cos_c - K(1e-5f) * (K(1.0f) + fabs(along));
    const scalar nearest = LANES_MIN(SEL(K(1e30f), along, live)), farthest = LANES_MAX(SEL(K(-1e30f), along, live));
    real best = bound, m = (real)(0.0f);
    scalar worst = OS_WORST(best, live);  // taken again only where a stale value would not decide
    bool stale = false;
    for (int k = 0; k < l->n; ++k) {
        if (stale && l->lo[k] - farthest <= worst && nearest - l->hi[k] <= worst)
            worst = OS_WORST(best, live), stale = false;
        if (l->lo[k] - farthest > worst) break;
        if (nearest - l->hi[k] > worst) continue;
        const int i = l->item[k];
        const real d = os_item(p, items + 4 * i, prims);
        m = SEL(m, (real)items[4 * i + 3], d < best);
        best = fmin(best, d);
        stale = true;
    }
    if (M_ANY(live & (best > depth))) return false;
    *d_out = best;
    *mat = m;
    return true;
}

//! fn os_cone_shading
//! deps: os_cone
//! class: helper
// The cone that shades a packet's hits: the camera cone's list, read by
// os_union_shade, and no culling by the camera's cone where the list
// cannot answer (os_union then walks the whole set). A list of the camera's
// cone alone (os_camera_cone did not widen it) would rarely answer for the
// taps beside the packet's edge: there the hits walk the set.
inline os_cone os_cone_shading(os_cone c)
{
    if (c.cos_w == c.cos_a) c.list = 0;
    c.on = 0;
    c.shade = 1;
    return c;
}
