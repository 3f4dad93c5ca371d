// Anisotropic GGX D * V (Walter 2007; Heitz 2014), height-correlated Smith, alpha = (ax, ay).
// D = 1/(pi ax ay q^2), q = hx^2/ax^2 + hy^2/ay^2 + hz^2.
float cnlm_ggx_dv(vec3 wo, vec3 wi, vec3 h, vec2 alpha) {
    if (!cnlm_both_upper(wo, wi) || h.z < 0.0) return 0.0;
    vec2 a = max(alpha, vec2(CNLM_ALPHA_MIRROR));
    vec2 hs = h.xy / a;
    float q = dot(hs, hs) + h.z * h.z;
    float d = 1.0 / (CNLM_PI * a.x * a.y * q * q);
    vec2 so = a * wo.xy, si = a * wi.xy;
    float len_o = sqrt(dot(so, so) + wo.z * wo.z);
    float len_i = sqrt(dot(si, si) + wi.z * wi.z);
    return d / (2.0 * (wi.z * len_o + wo.z * len_i));
}
