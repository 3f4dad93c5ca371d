// Weidlich & Wilkie 2007 coat helpers: refraction into the coat at the macro normal
// (same azimuth, sin' = sin / eta) and the Fresnel transmittance at entry and exit.
vec3 cnlm_refract_into_coat(vec3 w, float eta) {
    vec2 xy = w.xy / eta;
    float z = w.z > 0.0 ? sqrt(max(1.0 - dot(xy, xy), 0.0)) : 0.0;
    return vec3(xy, z);
}

float cnlm_coat_transmission(vec3 wo, vec3 wi, float eta) {
    if (!cnlm_both_upper(wo, wi)) return 0.0;
    return (1.0 - cnlm_fresnel_dielectric(wo.z, eta)) * (1.0 - cnlm_fresnel_dielectric(wi.z, eta));
}
