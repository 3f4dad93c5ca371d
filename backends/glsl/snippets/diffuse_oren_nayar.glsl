// Oren-Nayar qualitative model (1994, eq. 30), sigma in radians, without trigonometry:
// f = albedo/pi (A + B max(0, wi.wo - zi zo) / max(zi, zo)).
vec3 cnlm_oren_nayar(vec3 wo, vec3 wi, vec3 albedo, float sigma) {
    if (!cnlm_both_upper(wo, wi)) return vec3(0.0);
    float s2 = sigma * sigma;
    float a = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float b = 0.45 * s2 / (s2 + 0.09);
    float angular = max(dot(wo, wi) - wo.z * wi.z, 0.0) / max(wo.z, wi.z);
    return albedo * ((a + b * angular) / CNLM_PI);
}
