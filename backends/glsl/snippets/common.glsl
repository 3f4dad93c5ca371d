// cnlm common: constants and helpers of the local shading frame (n = +z, t = +x).
const float CNLM_PI = 3.14159265358979;
// cos(theta) below this counts as on/below the horizon: every lobe is 0 there.
const float CNLM_COS_EPS = 1e-7;
// alpha below this is a perfect mirror; lobes clamp alpha up to it (docs/bsdf.md).
const float CNLM_ALPHA_MIRROR = 1e-3;

bool cnlm_both_upper(vec3 wo, vec3 wi) {
    return wo.z >= CNLM_COS_EPS && wi.z >= CNLM_COS_EPS;
}

// normalize(wo + wi); the zero vector when wo = -wi.
vec3 cnlm_half_vector(vec3 wo, vec3 wi) {
    vec3 s = wo + wi;
    float len2 = dot(s, s);
    return len2 > 0.0 ? s * inversesqrt(len2) : vec3(0.0);
}

// cos(theta_d) as (wo.h + wi.h)/2: symmetric in wo, wi (reciprocity).
float cnlm_half_angle_cos(vec3 wo, vec3 wi, vec3 h) {
    return clamp(0.5 * (dot(wo, h) + dot(wi, h)), 0.0, 1.0);
}
