// cnlmc GLSL backend -- material "velvet"
// phrase: velvet
// model: diffuse + oren_nayar
// options: fresnel=exact, multiscatter=off, profile=330, form=both, specialize=on
//
// entry points:
//   vec3 cnlm_bsdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv)
//   vec3 cnlm_bsdf(vec3 n, vec3 v, vec3 l, vec2 uv)      (tangent from cnlm_any_tangent(n))
//   n surface normal, t surface tangent (streak direction of anisotropy, +U of the
//   normal map; bitangent = cross(n, t)), v towards the viewer, l towards the light:
//   unit vectors in any one space. Returns the BRDF f (linear Rec.709 RGB),
//   NOT multiplied by cos(theta_l).
// uniforms: (values also in the .glsl.json sidecar)
//   vec3 cnlm_base_color = vec3(0.3, 0.02, 0.05)
//   float cnlm_diffuse_roughness = 0.6
// samplers: none
uniform vec3 cnlm_base_color = vec3(0.3, 0.02, 0.05);
uniform float cnlm_diffuse_roughness = 0.6;
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

// A unit tangent orthogonal to n, continuous except at n.z = -1
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
vec3 cnlm_any_tangent(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
}

// Oren-Nayar qualitative model (1994, eq. 30), sigma in radians, without trigonometry:
// f = albedo/pi (A + B max(0, wi.wo - zi zo) / max(zi, zo)).
vec3 cnlm_oren_nayar(vec3 wo, vec3 wi, vec3 albedo, float sigma) {
    if (!cnlm_both_upper(wo, wi)) return vec3(0.0);
    float s2 = sigma * sigma;
    float a = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float b = 0.45 * s2 / (s2 + 0.09);
    float angular = max(dot(wo, wi) - wo.z * wi.z, 0.0) / max(wo.z, wi.z);
    return albedo * ((a + b * angular) / CNLM_PI);
}

// ---- material velvet: diffuse + oren_nayar ----

vec3 cnlm_surface_albedo(vec2 uv) {
    return cnlm_base_color;
}

vec3 cnlm_diffuse(vec3 wo, vec3 wi, vec3 albedo) {
    return cnlm_oren_nayar(wo, wi, albedo, cnlm_diffuse_roughness);
}

// The uncoated base, split into a directional (spec) and a diffuse-like (diff) part.
void cnlm_base(vec3 wo, vec3 wi, vec3 albedo, float outside,
               out vec3 spec, out vec3 diff) {
    spec = vec3(0.0);
    diff = cnlm_diffuse(wo, wi, albedo);
}

// The material in the local frame (n = +z, t = +x).
vec3 cnlm_bsdf_local(vec3 wo, vec3 wi, vec2 uv) {
    vec3 albedo = cnlm_surface_albedo(uv);
    vec3 spec, diff;
    cnlm_base(wo, wi, albedo, 1.0, spec, diff);
    vec3 f = spec + diff;
    return f;
}

vec3 cnlm_bsdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv) {
    vec3 tn = cnlm_any_tangent(n);
    vec3 bn = cross(n, tn);
    vec3 wo = vec3(dot(v, tn), dot(v, bn), dot(v, n));
    vec3 wi = vec3(dot(l, tn), dot(l, bn), dot(l, n));
    return cnlm_bsdf_local(wo, wi, uv);
}

vec3 cnlm_bsdf(vec3 n, vec3 v, vec3 l, vec2 uv) {
    return cnlm_bsdf(n, cnlm_any_tangent(n), v, l, uv);
}
