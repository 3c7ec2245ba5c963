//! fn env_lane
//! class: helper
// background.map reads its buffer per lane: ENV_LANE(v, i) is lane i of a
// real (the real itself at width 1).
#if SDFC_WIDTH == 1
#define ENV_LANE(v, i) (v)
#else
#define ENV_LANE(v, i) ((v)[i])
#endif
// The pixel of the map at (u, v) in [0, 1]^2, clamped to the map, as an index.
inline int env_pixel(scalar u, scalar v, int w, int h)
{
    int x = (u >= 0) ? min((int)(u * (scalar)w), w - 1) : 0;  // NaN and negatives go to pixel 0
    int y = (v >= 0) ? min((int)(v * (scalar)h), h - 1) : 0;
    return y * w + x;
}

//! fn env_uv
//! deps: vec3_ops
//! class: helper
// Where the unit direction d falls on an equirectangular map whose centre
// looks along e0, with e1 to its right and up at its top row: u across
// (azimuth), v down (polar angle), both in [0, 1].
inline void env_uv(vec3 d, vec3 e0, vec3 e1, vec3 up, real* u, real* v)
{
    real z = clamp(v3_dot(d, up), K(-1.0f), K(1.0f));
    *u = 0.5f + atan2(v3_dot(d, e1), v3_dot(d, e0)) * K(0.15915494309f);
    *v = acos(z) * K(0.31830988618f);
}

//! fn env_lookup
//! deps: env_lane, env_uv
//! class: helper
// The map's radiance along d (nearest pixel: the same piecewise-constant
// function the sampling tables describe).
inline vec3 env_lookup(__global const float* env, int w, int h, vec3 d, vec3 e0, vec3 e1, vec3 up)
{
    real u, v;
    env_uv(d, e0, e1, up, &u, &v);
    vec3 c = v3_splat(0.0f);
    for (int i = 0; i < SDFC_WIDTH; ++i) {
        __global const float* p = env + 3 * env_pixel(ENV_LANE(u, i), ENV_LANE(v, i), w, h);
        ENV_LANE(c.x, i) = p[0];
        ENV_LANE(c.y, i) = p[1];
        ENV_LANE(c.z, i) = p[2];
    }
    return c;
}

//! fn env_pdf
//! deps: env_lane, env_uv
//! class: helper
// The density (per solid angle) with which env_sample draws d: the pixel's
// share of the tables over its area on the sphere, 2 pi^2 sin(theta) / (w h).
inline real env_pdf(__global const float* env, int w, int h, vec3 d, vec3 e0, vec3 e1, vec3 up)
{
    real u, v;
    env_uv(d, e0, e1, up, &u, &v);
    __global const float* marginal = env + 3 * w * h;
    __global const float* rows = marginal + h + 1;
    real p = 0.0f;
    for (int i = 0; i < SDFC_WIDTH; ++i) {
        int at = env_pixel(ENV_LANE(u, i), ENV_LANE(v, i), w, h), y = at / w, x = at - y * w;
        __global const float* cdf = rows + y * (w + 1);
        ENV_LANE(p, i) = (marginal[y + 1] - marginal[y]) * (cdf[x + 1] - cdf[x]);
    }
    real s = fmax(sin(v * K(3.14159265359f)), K(1e-6f));
    return p * (real)((scalar)(w * h)) / (K(19.7392088022f) * s);
}

//! fn env_sample
//! deps: env_lane, vec3_ops
//! class: helper
// A direction drawn from the map's tables by two uniform numbers (a row by
// the marginal CDF, a pixel by that row's CDF, a uniform point inside it),
// its density per solid angle and the radiance there.
inline vec3 env_sample(__global const float* env, int w, int h, real u1, real u2, vec3 e0, vec3 e1, vec3 up,
                       real* pdf, vec3* radiance)
{
    __global const float* marginal = env + 3 * w * h;
    __global const float* rows = marginal + h + 1;
    real u = 0.0f, v = 0.0f, p = 0.0f;
    vec3 c = v3_splat(0.0f);
    for (int i = 0; i < SDFC_WIDTH; ++i) {
        scalar a = ENV_LANE(u1, i), b = ENV_LANE(u2, i);
        int lo = 0, hi = h;  // the row y with marginal[y] <= a < marginal[y + 1]
        while (hi - lo > 1) {
            int mid = (lo + hi) / 2;
            if (marginal[mid] <= a) lo = mid; else hi = mid;
        }
        const int y = lo;
        __global const float* cdf = rows + y * (w + 1);
        lo = 0, hi = w;
        while (hi - lo > 1) {
            int mid = (lo + hi) / 2;
            if (cdf[mid] <= b) lo = mid; else hi = mid;
        }
        const int x = lo;
        const scalar py = marginal[y + 1] - marginal[y], px = cdf[x + 1] - cdf[x];
        const scalar fy = py > 0 ? clamp((a - marginal[y]) / py, K(0.0f), K(1.0f)) : K(0.5f);
        const scalar fx = px > 0 ? clamp((b - cdf[x]) / px, K(0.0f), K(1.0f)) : K(0.5f);
        ENV_LANE(u, i) = ((scalar)x + fx) / (scalar)w;
        ENV_LANE(v, i) = ((scalar)y + fy) / (scalar)h;
        ENV_LANE(p, i) = py * px * (scalar)(w * h);
        __global const float* rgb = env + 3 * (y * w + x);
        ENV_LANE(c.x, i) = rgb[0];
        ENV_LANE(c.y, i) = rgb[1];
        ENV_LANE(c.z, i) = rgb[2];
    }
    real theta = v * K(3.14159265359f), phi = (u - 0.5f) * K(6.28318530718f);
    real s = sin(theta);
    *pdf = p / (K(19.7392088022f) * fmax(s, K(1e-6f)));
    *radiance = c;
    return v3_add(v3_add(v3_scale(e0, s * cos(phi)), v3_scale(e1, s * sin(phi))), v3_scale(up, cos(theta)));
}
