// Linear Rec.709 -> sRGB transfer function (IEC 61966-2-1), for display output.
vec3 cnlm_linear_to_srgb(vec3 c) {
    vec3 x = max(c, 0.0);
    vec3 lo = 12.92 * x;
    vec3 hi = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), x));
}
