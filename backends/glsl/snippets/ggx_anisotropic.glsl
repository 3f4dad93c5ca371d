// Anisotropic GGX D * V (Walter 2007; Heitz 2014), height-correlated Smith, alpha = (ax, ay).
// D = 1/(pi ax ay q^2), q = hx^2/ax^2 + hy^2/ay^2 + hz^2.
float cnlm_ggx_dv(vec3 wo, vec3 wi, vec3 h, vec2 alpha) {
    if (!cnlm_both_upper(wo, wi) || h.z < 0.0) return 0.0;
    vec2 a = max(alpha, vec2(CNLM_ALPHA_MIRROR));
    float d = cnlm_ggx_d_aniso(h, a);
    return d / (2.0 * (wi.z * cnlm_alpha_length(wo, a) + wo.z * cnlm_alpha_length(wi, a)));
}
