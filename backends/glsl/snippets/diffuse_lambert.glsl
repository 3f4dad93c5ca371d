// Lambert: f = albedo / pi (0 below the horizon).
vec3 cnlm_lambert(vec3 wo, vec3 wi, vec3 albedo) {
    return cnlm_both_upper(wo, wi) ? albedo / CNLM_PI : vec3(0.0);
}
