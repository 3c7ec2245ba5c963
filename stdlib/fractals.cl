//! fn de_mandelbulb
//! deps: de_bulb_trig
//! class: estimate
// White-Nylander Mandelbulb for any real power, analytic running-derivative
// estimator d = 0.5 log(r) r / dr (seed 000, 001 part V): the orbit
// z <- z^n + p, so dr gains + 1 each step. Integer powers use the trig-free
// de_mandelbulb_int instead.
inline real de_mandelbulb(vec3 p, real power, int iterations, real bailout, real set_radius)
{
    return de_bulb_trig(p, p, 1.0f, power, iterations, bailout, set_radius);
}
