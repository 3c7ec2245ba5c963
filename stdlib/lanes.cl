//! fn lanes_minmax
//! class: helper
// The smallest and the largest of a packet's lanes, as one scalar: the
// halves compared lane by lane (a < b ? a : b), log2(width) vector steps.
// Clang's __builtin_reduce_min/max keep fmin's NaN rules, which x86 has no
// vector instruction for: they went one lane at a time, a chain of
// dependent steps, and the object list's loop, which takes one per item,
// spent most of its time there (flat 10 000 objects: 34 ms a frame against
// 25). A NaN lane may or may not win here: callers use the result only to
// skip work that could not change a value, or with every lane a number.
#if SDFC_WIDTH == 1
#define LANES_MIN(x) (x)
#define LANES_MAX(x) (x)
#else
// the larger (take_max) or smaller of v's two halves, lane by lane
#define LANES_HALF(v, take_max) \
    ((take_max) ? ((v).lo > (v).hi ? (v).lo : (v).hi) : ((v).lo < (v).hi ? (v).lo : (v).hi))
inline scalar lanes_reduce(real x, const bool take_max)
{
#if SDFC_WIDTH >= 64
    __auto_type x32 = LANES_HALF(x, take_max);
#elif SDFC_WIDTH == 32
    __auto_type x32 = x;
#endif
#if SDFC_WIDTH >= 32
    __auto_type x16 = LANES_HALF(x32, take_max);
#elif SDFC_WIDTH == 16
    __auto_type x16 = x;
#endif
#if SDFC_WIDTH >= 16
    __auto_type x8 = LANES_HALF(x16, take_max);
#elif SDFC_WIDTH == 8
    __auto_type x8 = x;
#endif
#if SDFC_WIDTH >= 8
    __auto_type x4 = LANES_HALF(x8, take_max);
#elif SDFC_WIDTH == 4
    __auto_type x4 = x;
#endif
#if SDFC_WIDTH >= 4
    __auto_type x2 = LANES_HALF(x4, take_max);
#else
    __auto_type x2 = x;
#endif
    return LANES_HALF(x2, take_max);
}
#define LANES_MIN(x) lanes_reduce((x), false)
#define LANES_MAX(x) lanes_reduce((x), true)
#endif
