// Exact unpolarised Fresnel reflectance of a dielectric, relative IOR eta (Born & Wolf).
// Total internal reflection gives 1; eta = 1 gives exactly 0.
float cnlm_fresnel_dielectric(float cos_theta, float eta) {
    if (eta == 1.0) return 0.0;
    float c = clamp(abs(cos_theta), 0.0, 1.0);
    float ct2 = ((eta * eta - 1.0) + c * c) / (eta * eta);
    if (ct2 < 0.0) return 1.0;
    float ct = sqrt(ct2);
    float rs_den = c + eta * ct;
    float rp_den = eta * c + ct;
    float rs = rs_den != 0.0 ? (c - eta * ct) / rs_den : 0.0;
    float rp = rp_den != 0.0 ? (eta * c - ct) / rp_den : 0.0;
    return 0.5 * (rs * rs + rp * rp);
}
