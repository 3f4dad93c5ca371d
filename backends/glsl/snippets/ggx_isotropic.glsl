// Isotropic GGX D * V (Walter 2007; Heitz 2014), height-correlated Smith.
// D = 1/(pi a^2 q^2), q = (hx^2 + hy^2)/a^2 + hz^2: no cancellation down to a = 1e-3.
// V = 1/(2(zi |wo|_a + zo |wi|_a)), |w|_a = sqrt(a^2 (wx^2 + wy^2) + wz^2): finite at grazing.
float cnlm_ggx_dv(vec3 wo, vec3 wi, vec3 h, float alpha) {
    if (!cnlm_both_upper(wo, wi) || h.z < 0.0) return 0.0;
    float a = max(alpha, CNLM_ALPHA_MIRROR);
    float a2 = a * a;
    float q = dot(h.xy, h.xy) / a2 + h.z * h.z;
    float d = 1.0 / (CNLM_PI * a2 * q * q);
    float len_o = sqrt(a2 * dot(wo.xy, wo.xy) + wo.z * wo.z);
    float len_i = sqrt(a2 * dot(wi.xy, wi.xy) + wi.z * wi.z);
    return d / (2.0 * (wi.z * len_o + wo.z * len_i));
}
