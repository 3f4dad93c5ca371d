#version 330 core
// Standalone preview shader: one directional light plus a constant ambient term.
// Output: sRGB-encoded colour (linear radiance through the sRGB transfer function),
// for a plain 8-bit default framebuffer.
// cnlmc GLSL backend -- material "polished_gold"
// phrase: polished gold
// model: conductor + ggx + fresnel f82
// options: fresnel=f82, multiscatter=off, profile=330, form=both, specialize=on
//
// entry points:
//   vec3 cnlm_bsdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv)
//   vec3 cnlm_bsdf(vec3 n, vec3 v, vec3 l, vec2 uv)      (tangent from cnlm_any_tangent(n))
//   n surface normal, t surface tangent (streak direction of anisotropy, +U of the
//   normal map; bitangent = cross(n, t)), v towards the viewer, l towards the light:
//   unit vectors in any one space. Returns the BRDF f (linear Rec.709 RGB),
//   NOT multiplied by cos(theta_l).
// uniforms: (values also in the .glsl.json sidecar)
//   vec3 cnlm_base_color = vec3(1.0, 1.0, 1.0)
//   float cnlm_alpha = 0.001
//   vec3 cnlm_f0 = vec3(0.9992, 0.7285, 0.3645)
//   vec3 cnlm_f82 = vec3(0.991, 0.8572, 0.6464)
// samplers: none
uniform vec3 cnlm_base_color = vec3(1.0, 1.0, 1.0);
uniform float cnlm_alpha = 0.001;
uniform vec3 cnlm_f0 = vec3(0.9992, 0.7285, 0.3645);
uniform vec3 cnlm_f82 = vec3(0.991, 0.8572, 0.6464);
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

// Hoffman 2019 "F82": Schlick corrected to pass through the measured F82 at mu = 1/7.
// Clipped below at 0 only (measured F0 may exceed 1 in linear sRGB).
vec3 cnlm_fresnel_f82(float cos_theta, vec3 f0, vec3 f82) {
    const float MU_BAR = 1.0 / 7.0;
    float c = clamp(abs(cos_theta), 0.0, 1.0);
    float m = 1.0 - c;
    float m3 = m * m * m;
    float mb = 1.0 - MU_BAR;
    float mb3 = mb * mb * mb;
    float shape = c * m3 * m3 / (MU_BAR * mb3 * mb3);
    vec3 dip = cnlm_fresnel_schlick(MU_BAR, f0) - f82;
    return max(cnlm_fresnel_schlick(c, f0) - dip * shape, 0.0);
}

// Isotropic GGX D * V (Walter 2007; Heitz 2014), height-correlated Smith.
// D = 1/(pi a^2 q^2), q = (hx^2 + hy^2)/a^2 + hz^2: no cancellation down to a = 1e-3.
// V = 1/(2(zi |wo|_a + zo |wi|_a)), |w|_a = sqrt(a^2 (wx^2 + wy^2) + wz^2): finite at grazing.
float cnlm_ggx_dv(vec3 wo, vec3 wi, vec3 h, float alpha) {
    if (!cnlm_both_upper(wo, wi) || h.z < 0.0) return 0.0;
    float a = max(alpha, CNLM_ALPHA_MIRROR);
    float a2 = a * a;
    float q = dot(h.xy, h.xy) / a2 + h.z * h.z;
    float d = 1.0 / (CNLM_PI * a2 * q * q);
    float len_o = sqrt(a2 * dot(wo.xy, wo.xy) + wo.z * wo.z);
    float len_i = sqrt(a2 * dot(wi.xy, wi.xy) + wi.z * wi.z);
    return d / (2.0 * (wi.z * len_o + wo.z * len_i));
}

// ---- material polished_gold: conductor + ggx + fresnel f82 ----

vec3 cnlm_surface_albedo(vec2 uv) {
    return cnlm_base_color;
}

float cnlm_surface_alpha(vec2 uv) {
    return cnlm_alpha;
}

// The base's Fresnel at cos theta; `outside` is the IOR above the base (1, or the coat's).
vec3 cnlm_base_fresnel(float c, float outside) {
    return cnlm_fresnel_f82(c, cnlm_f0, cnlm_f82);
}

// Specular lobe F(wo.h) D V (ggx).
vec3 cnlm_specular(vec3 wo, vec3 wi, float alpha, float outside) {
    vec3 h = cnlm_half_vector(wo, wi);
    float dv = cnlm_ggx_dv(wo, wi, h, alpha);
    if (dv == 0.0) return vec3(0.0);
    return dv * cnlm_base_fresnel(cnlm_half_angle_cos(wo, wi, h), outside);
}

// The uncoated base, split into a directional (spec) and a diffuse-like (diff) part.
void cnlm_base(vec3 wo, vec3 wi, vec3 albedo, float alpha, float outside,
               out vec3 spec, out vec3 diff) {
    spec = albedo * cnlm_specular(wo, wi, alpha, outside);
    diff = vec3(0.0);
}

// The material in the local frame (n = +z, t = +x).
vec3 cnlm_bsdf_local(vec3 wo, vec3 wi, vec2 uv) {
    vec3 albedo = cnlm_surface_albedo(uv);
    vec3 spec, diff;
    cnlm_base(wo, wi, albedo, cnlm_surface_alpha(uv), 1.0, spec, diff);
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

// ---- standalone shading ----
// Linear Rec.709 -> sRGB transfer function (IEC 61966-2-1), for display output.
vec3 cnlm_linear_to_srgb(vec3 c) {
    vec3 x = max(c, 0.0);
    vec3 lo = 12.92 * x;
    vec3 hi = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), x));
}

in vec3 v_position;
in vec3 v_normal;
in vec3 v_tangent;
in vec2 v_uv;

uniform vec3 cnlm_camera_position;
// Direction towards the light (world space), its radiance and the ambient radiance.
uniform vec3 cnlm_light_direction = vec3(0.4, 0.6, 0.7);
uniform vec3 cnlm_light_radiance = vec3(3.0);
uniform vec3 cnlm_ambient_radiance = vec3(0.05);

out vec4 cnlm_frag_color;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 v = normalize(cnlm_camera_position - v_position);
    vec3 l = normalize(cnlm_light_direction);
    vec3 direct = cnlm_bsdf(n, v_tangent, v, l, v_uv) * cnlm_light_radiance * max(dot(n, l), 0.0);
    // Constant ambient: A(v) ~ pi f(v, n) (exact for Lambert; the preview adds IBL later).
    vec3 ambient = cnlm_ambient_radiance * CNLM_PI * cnlm_bsdf(n, v_tangent, v, n, v_uv);
    cnlm_frag_color = vec4(cnlm_linear_to_srgb(direct + ambient), 1.0);
}
