// Schlick 1994: F = F0 + (1 - F0)(1 - cos)^5.
vec3 cnlm_fresnel_schlick(float cos_theta, vec3 f0) {
    float m = 1.0 - clamp(abs(cos_theta), 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Normal-incidence reflectance of a dielectric: ((eta - 1)/(eta + 1))^2.
float cnlm_f0_from_ior(float eta) {
    float r = (eta - 1.0) / (eta + 1.0);
    return r * r;
}
