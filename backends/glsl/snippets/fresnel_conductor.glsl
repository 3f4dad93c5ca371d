// Exact unpolarised Fresnel reflectance of a conductor, eta + i k per RGB channel
// (Born & Wolf 13.2; Lazanyi & Szirmay-Kalos 2005), real arithmetic only.
vec3 cnlm_fresnel_conductor(float cos_theta, vec3 eta, vec3 k) {
    float c = clamp(abs(cos_theta), 0.0, 1.0);
    float c2 = c * c;
    float s2 = 1.0 - c2;
    vec3 t0 = (eta * eta - 1.0) - k * k + c2;
    vec3 a2b2 = sqrt(t0 * t0 + 4.0 * eta * eta * k * k);
    vec3 a = sqrt(max(0.5 * (a2b2 + t0), 0.0));
    vec3 rs = (a2b2 - 2.0 * a * c + c2) / max(a2b2 + 2.0 * a * c + c2, 1e-30);
    vec3 p_num = c2 * a2b2 - 2.0 * a * c * s2 + s2 * s2;
    vec3 p_den = c2 * a2b2 + 2.0 * a * c * s2 + s2 * s2;
    vec3 rp = rs * p_num / max(p_den, 1e-30);
    return clamp(0.5 * (rs + rp), 0.0, 1.0);
}
