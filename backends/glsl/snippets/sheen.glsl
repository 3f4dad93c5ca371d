// The Charlie sheen over the base (Estevez & Kulla 2017; cnlmc.bsdf.sheen, docs/bsdf.md "Sheen"):
// f = cnlm_sheen_color * D V + f_base * (1 - s max(E(mu_o), E(mu_i))), s = max(cnlm_sheen_color),
// D(h) = (2 + 1/a) sin^(1/a) theta_h / 2pi, V = 1 / ((1 + L(mu_o) + L(mu_i)) 4 mu_o mu_i) with the
// paper's fitted Lambda; E the white sheen's albedo at the material's alpha (cnlm_sheen_albedo,
// the reference's row: 32 nodes uniform in sqrt mu).
float cnlm_charlie_l(float x, float a) {
    float t = (1.0 - a) * (1.0 - a);
    float ca = mix(21.5473, 25.3245, t), cb = mix(3.82987, 3.32435, t), cc = mix(0.19823, 0.16801, t);
    float cd = mix(-1.97760, -1.27393, t), ce = mix(-4.32054, -4.85967, t);
    return ca / (1.0 + cb * pow(x, cc)) + cd * x + ce;
}

float cnlm_charlie_lambda(float mu, float a) {
    float e = mu < 0.5 ? cnlm_charlie_l(mu, a) : 2.0 * cnlm_charlie_l(0.5, a) - cnlm_charlie_l(1.0 - mu, a);
    return exp(min(e, 80.0));
}

float cnlm_sheen_dv(vec3 wo, vec3 wi, float a) {
    if (wo.z < CNLM_COS_EPS || wi.z < CNLM_COS_EPS) return 0.0;
    vec3 h = cnlm_half_vector(wo, wi);
    float inv = 1.0 / a;
    float d = (2.0 + inv) * pow(max(1.0 - h.z * h.z, 0.0), 0.5 * inv) / (2.0 * CNLM_PI);
    float g2 = 1.0 / (1.0 + cnlm_charlie_lambda(wo.z, a) + cnlm_charlie_lambda(wi.z, a));
    return d * g2 / (4.0 * wo.z * wi.z);
}

float cnlm_sheen_e(float mu) {
    float x = sqrt(clamp(mu, 0.0, 1.0)) * 31.0;
    int i = min(int(floor(x)), 30);
    return mix(cnlm_sheen_albedo[i], cnlm_sheen_albedo[i + 1], x - float(i));
}

vec3 cnlm_sheen_layer(vec3 wo, vec3 wi, vec3 base) {
    float s = max(cnlm_sheen_color.r, max(cnlm_sheen_color.g, cnlm_sheen_color.b));
    float e = max(cnlm_sheen_e(wo.z), cnlm_sheen_e(wi.z));
    return cnlm_sheen_color * cnlm_sheen_dv(wo, wi, cnlm_sheen_alpha) + base * max(1.0 - s * e, 0.0);
}
