//! fn shade_blinn_phong
//! deps: vec3_ops
//! class: helper
// One light's Blinn-Phong contribution. l points from the surface to the
// light, v from the surface to the eye; radiance is colour * intensity.
// x^s as exp2(s log2 x) on x >= 1e-30 (so 0^0 stays 1): the builtin pow's
// special cases and extended-precision log cost about as much as the rest
// of the shading.
inline vec3 shade_blinn_phong(vec3 n, vec3 l, vec3 v, vec3 albedo, real specular,
                              real shininess, vec3 radiance)
{
    real ndl = fmax(v3_dot(n, l), K(0.0f));
    vec3 h = v3_normalize(v3_add(l, v));
    real spec = SEL((real)0.0f, specular * exp2(shininess * log2(fmax(v3_dot(n, h), K(1e-30f)))), ndl > 0.0f);
    return v3_mul(radiance, v3_add(v3_scale(albedo, ndl), v3_splat(spec)));
}

//! fn shade_background
//! deps: vec3_ops
//! class: helper
// Vertical gradient by the ray's elevation against the scene's up vector.
inline vec3 shade_background(vec3 rd, vec3 up, vec3 top, vec3 bottom)
{
    real s = clamp(0.5f + 0.5f * v3_dot(rd, up), K(0.0f), K(1.0f));
    return v3_mix(bottom, top, s);
}

//! fn shade_encode
//! deps: vec3_ops
//! class: helper
// Linear colour to display values: clamp, then gamma, as exp2(g log2 c)
// rather than pow, whose extended-precision log costs more; 1e-30 maps to 0.
inline vec3 shade_encode(vec3 c, real inv_gamma)
{
    c = v3(clamp(c.x, K(1e-30f), K(1.0f)), clamp(c.y, K(1e-30f), K(1.0f)), clamp(c.z, K(1e-30f), K(1.0f)));
    return v3(exp2(inv_gamma * log2(c.x)), exp2(inv_gamma * log2(c.y)), exp2(inv_gamma * log2(c.z)));
}
