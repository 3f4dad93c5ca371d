// Hoffman 2019 "F82": Schlick corrected to pass through the measured F82 at mu = 1/7.
// Clipped below at 0 only (measured F0 may exceed 1 in linear sRGB).
vec3 cnlm_fresnel_f82(float cos_theta, vec3 f0, vec3 f82) {
    const float MU_BAR = 1.0 / 7.0;
    float c = clamp(abs(cos_theta), 0.0, 1.0);
    float m = 1.0 - c;
    float m3 = m * m * m;
    float mb = 1.0 - MU_BAR;
    float mb3 = mb * mb * mb;
    float shape = c * m3 * m3 / (MU_BAR * mb3 * mb3);
    vec3 dip = cnlm_fresnel_schlick(MU_BAR, f0) - f82;
    return max(cnlm_fresnel_schlick(c, f0) - dip * shape, 0.0);
}
