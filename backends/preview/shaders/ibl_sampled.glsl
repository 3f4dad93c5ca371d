// ---- tiers "mc<N>" and "fis<N>": Monte Carlo integration of f * L * cos over the hemisphere.
// Multi-sample MIS (balance heuristic) over cosine, base-GGX and coat-GGX visible-normal
// sampling; every sample evaluates cnlm_bsdf exactly. mc: per-pixel rotated Hammersley, full
// resolution environment (unbiased, noisy). fis: one sequence for all pixels and a mip level
// from the sample's pdf (Krivanek & Colbert 2008: smooth, slightly blurred).
uniform int pv_samples;
uniform int pv_filtered;
uniform vec2 pv_env_size;

float pv_mis_pdf(vec3 wo, vec3 wi, float a_spec, float a_coat, vec3 share) {
    return share.x * pv_pdf_cosine(wi) + share.y * pv_pdf_vndf(wo, wi, a_spec) + share.z * pv_pdf_vndf(wo, wi, a_coat);
}

vec3 pv_ibl(vec3 ng, vec3 ns, vec3 t, vec3 v, vec2 uv) {
    mat3 frame = pv_frame(ns, t);
    vec3 wo = vec3(dot(v, frame[0]), dot(v, frame[1]), dot(v, frame[2]));
    if (wo.z <= 0.0) return vec3(0.0);
    float a_spec = max(pv_spec_alpha(uv), CNLM_ALPHA_MIRROR), a_coat = pv_coat_alpha();
    vec2 shift = pv_filtered == 1 ? vec2(0.0)
               : vec2(pv_hash(uint(gl_FragCoord.x) * 7919u + uint(gl_FragCoord.y) * 104729u),
                      pv_hash(uint(gl_FragCoord.y) * 15485863u + uint(gl_FragCoord.x) * 32452843u)) * 2.3283064365386963e-10;
    int n_total = max(pv_samples, 1);
    float texel = 4.0 * PV_PI / (pv_env_size.x * pv_env_size.y);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < n_total; ++i) {
        vec2 xi = pv_hammersley(i, n_total, shift);
        // Strategy by stratum of the first coordinate (stratified one-sample MIS).
        vec3 wi;
        if (xi.x < PV_STRATEGY.x) {
            wi = pv_sample_cosine(vec2(xi.x / PV_STRATEGY.x, xi.y));
        } else if (xi.x < PV_STRATEGY.x + PV_STRATEGY.y) {
            vec3 h = pv_sample_vndf(wo, a_spec, vec2((xi.x - PV_STRATEGY.x) / PV_STRATEGY.y, xi.y));
            wi = reflect(-wo, h);
        } else {
            vec3 h = pv_sample_vndf(wo, a_coat, vec2((xi.x - PV_STRATEGY.x - PV_STRATEGY.y) / PV_STRATEGY.z, xi.y));
            wi = reflect(-wo, h);
        }
        if (wi.z <= 0.0) continue;
        float pdf = pv_mis_pdf(wo, wi, a_spec, a_coat, PV_STRATEGY);
        if (!(pdf > 0.0)) continue;
        vec3 l = frame * wi;
        float lod = pv_filtered == 1 ? max(0.5 * log2(1.0 / (float(n_total) * pdf * texel)) + 1.0, 0.0) : 0.0;
        sum += cnlm_bsdf(ng, t, v, l, uv) * wi.z / pdf * pv_env_lod(l, lod);
    }
    return sum / float(n_total);
}
