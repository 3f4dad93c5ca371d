// Rough dielectric transmission, Walter et al. 2007 eq. 21, GGX with the height-correlated
// Smith G2 = 1/(1 + L(wo) + L(wi)) of the reflection lobe (directions mirrored to z > 0).
// Outside (index 1) is z > 0, inside (index ior) z < 0; eta_o / eta_i index of wo's / wi's side.
//   s = eta_i wi + eta_o wo,  h = -s/|s| flipped to h.z >= 0 (generalized half vector)
//   f_t = |wi.h||wo.h| eta_o^2 (1 - F) D(h) G2 / (|s|^2 |wo.z||wi.z|)      (radiance transport)
//       = |wi.h||wo.h| eta_o^2 (1 - F) D(h) 2 / (|s|^2 (|wi.z| |wo|_a + |wo.z| |wi|_a)):  no 1/cos.
// Returns f_t / (1 - F) and the outside direction's cos against h (for F; the same from both
// sides). 0 for same-side pairs, |cos| < CNLM_COS_EPS, ior = 1 (a delta: wi = -wo) and pairs
// no microfacet can refract (total internal reflection region).
float cnlm_ggx_btdf(vec3 wo, vec3 wi, vec2 alpha, float ior, out float cos_out) {
    cos_out = 0.0;
    if (ior == 1.0 || abs(wo.z) < CNLM_COS_EPS || abs(wi.z) < CNLM_COS_EPS || wo.z * wi.z >= 0.0)
        return 0.0;
    float eta_o = wo.z > 0.0 ? 1.0 : ior;
    float eta_i = wi.z > 0.0 ? 1.0 : ior;
    vec3 s = eta_i * wi + eta_o * wo;
    float s2 = dot(s, s);
    if (s2 <= 0.0) return 0.0;
    vec3 h = -s * inversesqrt(s2);
    if (h.z < 0.0) h = -h;
    float oh = dot(wo, h);
    float ih = dot(wi, h);
    if (oh * wo.z <= 0.0 || ih * wi.z <= 0.0 || h.z <= 0.0) return 0.0;
    cos_out = abs(wo.z > 0.0 ? oh : ih);
    vec2 a = max(alpha, vec2(CNLM_ALPHA_MIRROR));
    float d = cnlm_ggx_d_aniso(h, a);
    float g_over_cos = 2.0 / (abs(wi.z) * cnlm_alpha_length(wo, a) + abs(wo.z) * cnlm_alpha_length(wi, a));
    return abs(oh * ih) * eta_o * eta_o * d * g_over_cos / s2;
}

float cnlm_ggx_btdf(vec3 wo, vec3 wi, float alpha, float ior, out float cos_out) {
    return cnlm_ggx_btdf(wo, wi, vec2(alpha), ior, cos_out);
}
