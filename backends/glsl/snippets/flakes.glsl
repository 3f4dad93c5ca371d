// Flakes in a paint under its coat (cnlmc.bsdf.flakes, docs/bsdf.md "Flakes"): a population of
// mirror-like flakes whose normals follow GGX of width cnlm_flake_alpha, Schlick F0 =
// cnlm_flake_color; a share cnlm_flake_density of the base (mixed in by cnlm_base), hiding it by
// what a flake reflects, max(cnlm_flake_color) (a pearl platelet lets the rest through).
float cnlm_flake_keep() {
    return 1.0 - cnlm_flake_density * max(cnlm_flake_color.r, max(cnlm_flake_color.g, cnlm_flake_color.b));
}

vec3 cnlm_flake_lobe(vec3 wo, vec3 wi) {
    vec3 h = cnlm_half_vector(wo, wi);
    float dv = cnlm_ggx_dv(wo, wi, h, cnlm_flake_alpha);
    if (dv == 0.0) return vec3(0.0);
    return dv * cnlm_fresnel_schlick(cnlm_half_angle_cos(wo, wi, h), cnlm_flake_color);
}
