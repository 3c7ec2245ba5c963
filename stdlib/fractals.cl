//! fn de_mandelbulb
//! deps: vec3_ops
//! class: estimate
// White-Nylander Mandelbulb, analytic running-derivative estimator
// d = 0.5 log(r) r / dr (seed 000, 001 part V). Lanes leave the orbit loop
// as they pass the bailout; the loop ends when every lane has.
// Far from the set the potential estimate overshoots, so outside 1.5x the
// radius that contains the set we return the distance to that sphere, which
// is a true lower bound.
inline real de_mandelbulb(vec3 p, real power, int iterations, real bailout, real set_radius)
{
    vec3 z = p;
    real dr = 1.0f;
    real r = v3_length(z);
    mask alive = r < bailout;
    for (int i = 0; i < iterations && M_ANY(alive); ++i) {
        real rs = fmax(r, K(1e-20f));
        real theta = acos(clamp(z.z / rs, K(-1.0f), K(1.0f))) * power;
        real phi = atan2(z.y, z.x) * power;
        real rp = pow(rs, power - 1.0f);
        real dr_next = rp * power * dr + 1.0f;
        real zr = rp * rs;
        real st = sin(theta);
        vec3 z_next = v3(zr * st * cos(phi) + p.x, zr * st * sin(phi) + p.y, zr * cos(theta) + p.z);
        z = v3_select(z, z_next, alive);
        dr = SEL(dr, dr_next, alive);
        r = v3_length(z);
        alive = alive & (r < bailout);
    }
    real de = 0.5f * log(fmax(r, K(1e-20f))) * r / dr;
    real r0 = v3_length(p);
    return SEL(de, r0 - set_radius, r0 > 1.5f * set_radius);
}
