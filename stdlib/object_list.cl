//! fn os_list
//! deps: os_cone, os_item
//! class: helper
// The items of an object set in a packet's camera cone, in the order their
// bounding balls begin along the cone's axis: gathered once per packet
// (os_list_gather), so that each step of the camera march measures only the
// items some live lane may still reach (os_union_list) instead of walking
// the hierarchy. A scene with one object set only: the list is that set's.
// A cone holding more items than OS_LIST_CAP keeps the walk (n = -1).
#if SDFC_WIDTH == 1
#define OS_LIST_CAP 16
#else
#define OS_LIST_CAP 64
#endif
#define OS_LIST_STACK 64
typedef struct os_list
{
    int n;                                    // items held; -1: too many, walk the hierarchy
    int first;                                // the first not yet behind every live lane
    int item[OS_LIST_CAP];                    // the item's index in the set
    scalar lo[OS_LIST_CAP], hi[OS_LIST_CAP];  // where its balls begin and end along the axis
} os_list;

// Inserts item i, spanning [lo, hi] along the axis, in order of lo.
inline bool os_list_add(os_list* l, int i, scalar lo, scalar hi)
{
    if (l->n == OS_LIST_CAP) return false;
    int k = l->n++;
    for (; k > 0 && l->lo[k - 1] > lo; --k) {
        l->item[k] = l->item[k - 1];
        l->lo[k] = l->lo[k - 1];
        l->hi[k] = l->hi[k - 1];
    }
    l->item[k] = i;
    l->lo[k] = lo;
    l->hi[k] = hi;
    return true;
}

// Every item of the set (nodes and items as os_union reads them) that
// reaches into the cone, with the span of its balls (os_item_in_cone's:
// each shape's, grown by a quarter of the blend radius) along the axis.
inline void os_list_gather(os_list* l, const os_cone c, __global const float* s, const int n_nodes, const int n_items)
{
    __global const float* items = s + 8 * n_nodes;
    __global const float* prims = items + 4 * n_items;
    l->n = c.on ? 0 : -1;
    l->first = 0;
    int stack[OS_LIST_STACK];
    int top = 0;
    if (c.on) stack[top++] = 0;
    while (top > 0) {
        const int node = stack[--top];
        __global const float* b = s + 8 * node;
        if (!os_in_cone(c, b)) continue;
        const int first = (int)b[6], count = (int)b[7];
        if (count == 0) {
            stack[top++] = first;
            stack[top++] = node + 1;
            continue;
        }
        for (int i = first; i < first + count; ++i) {
            __global const float* item = items + 4 * i;
            if (!os_item_in_cone(c, item, prims)) continue;
            __global const float* r = prims + 8 * (int)item[0];
            const scalar reach = os_item_reach(item);
            scalar lo = 1e30f, hi = -1e30f;
            for (int k = 0; k < (int)item[1]; ++k, r += 8) {
                const scalar along = (r[1] - c.ox) * c.ax + (r[2] - c.oy) * c.ay + (r[3] - c.oz) * c.az;
                const scalar radius = os_prim_radius(r) + reach;
                lo = fmin(lo, along - radius);
                hi = fmax(hi, along + radius);
            }
            if (!os_list_add(l, i, lo, hi)) {
                l->n = -1;
                return;
            }
        }
    }
}

//! fn os_union_list
//! deps: os_list
//! class: bound
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
    const scalar nearest = OS_LANES_MIN(SEL(K(1e30f), along, live)), farthest = OS_LANES_MAX(SEL(K(-1e30f), along, live));
    // twice the hit band at the farthest lane (t is at most along / cos a)
    const scalar behind = nearest - c.margin * farthest / c.cos_a;
    while (l->first < l->n && l->hi[l->first] < behind) ++l->first;
    real best = bound, m = (real)(0.0f);
    for (int k = l->first; k < l->n; ++k) {
        if (l->lo[k] - farthest > OS_LANES_MAX(SEL(K(-1e30f), best, live))) break;
        if (l->hi[k] < behind) continue;
        const int i = l->item[k];
        const real d = os_item(p, items + 4 * i, prims);
        m = SEL(m, (real)items[4 * i + 3], d < best);
        best = fmin(best, d);
    }
    *mat = m;
    return best;
}
