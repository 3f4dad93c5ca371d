#version 330 core
// Standalone preview shader: one directional light plus a constant ambient term.
// Output: sRGB-encoded colour (linear radiance through the sRGB transfer function),
// for a plain 8-bit default framebuffer.
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
//   vec3 cnlm_sheen_color = vec3(0.8, 0.104959, 0.208678)
//   float cnlm_sheen_alpha = 0.25
//   float[32] cnlm_sheen_albedo = float[32](0.654659315, 0.745665876, 0.79958077, 0.80333681, 0.783816993, 0.752809645, 0.716196955, 0.677126903, 0.637340788, 0.597808922, 0.559062721, 0.521379018, 0.484886922, 0.449631708, 0.415613831, 0.382813037, 0.351203233, 0.320761478, 0.291473088, 0.263334095, 0.236351848, 0.210544279, 0.185941164, 0.16301946, 0.141857047, 0.122162116, 0.103721242, 0.0863874367, 0.0700706251, 0.0547291294, 0.0403608342, 0.026982025)
// samplers: none
uniform vec3 cnlm_base_color = vec3(0.3, 0.02, 0.05);
uniform float cnlm_diffuse_roughness = 0.6;
uniform vec3 cnlm_sheen_color = vec3(0.8, 0.104959, 0.208678);
uniform float cnlm_sheen_alpha = 0.25;
uniform float[32] cnlm_sheen_albedo = float[32](0.654659315, 0.745665876, 0.79958077, 0.80333681, 0.783816993, 0.752809645, 0.716196955, 0.677126903, 0.637340788, 0.597808922, 0.559062721, 0.521379018, 0.484886922, 0.449631708, 0.415613831, 0.382813037, 0.351203233, 0.320761478, 0.291473088, 0.263334095, 0.236351848, 0.210544279, 0.185941164, 0.16301946, 0.141857047, 0.122162116, 0.103721242, 0.0863874367, 0.0700706251, 0.0547291294, 0.0403608342, 0.026982025);
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

// The Charlie sheen over the base (Estevez & Kulla 2017; cnlmc.bsdf.sheen, docs/bsdf.md "Sheen"):
// f = cnlm_sheen_color * D V + f_base * (1 - s max(E(mu_o), E(mu_i))), s = max(cnlm_sheen_color),
// D(h) = (2 + 1/a) sin^(1/a) theta_h / 2pi, V = 1 / ((1 + L(mu_o) + L(mu_i)) 4 mu_o mu_i) with the
// paper's fitted Lambda; E the white sheen's albedo at the material's alpha (cnlm_sheen_albedo,
// the reference's row: 32 nodes uniform in sqrt mu).
float cnlm_charlie_l(float x, float a) {
    float t = (1.0 - a) * (1.0 - a);
    float ca = mix(21.5473, 25.3245, t), cb = mix(3.82987, 3.32435, t), cc = mix(0.19823, 0.16801, t);
    float cd = mix(-1.97760, -1.27393, t), ce = mix(-4.32054, -4.85967, t);
    return ca / (1.0 + cb * pow(x, cc)) + cd * x + ce;
}

float cnlm_charlie_lambda(float mu, float a) {
    float e = mu < 0.5 ? cnlm_charlie_l(mu, a) : 2.0 * cnlm_charlie_l(0.5, a) - cnlm_charlie_l(1.0 - mu, a);
    return exp(min(e, 80.0));
}

float cnlm_sheen_dv(vec3 wo, vec3 wi, float a) {
    if (wo.z < CNLM_COS_EPS || wi.z < CNLM_COS_EPS) return 0.0;
    vec3 h = cnlm_half_vector(wo, wi);
    float inv = 1.0 / a;
    float d = (2.0 + inv) * pow(max(1.0 - h.z * h.z, 0.0), 0.5 * inv) / (2.0 * CNLM_PI);
    float g2 = 1.0 / (1.0 + cnlm_charlie_lambda(wo.z, a) + cnlm_charlie_lambda(wi.z, a));
    return d * g2 / (4.0 * wo.z * wi.z);
}

float cnlm_sheen_e(float mu) {
    float x = sqrt(clamp(mu, 0.0, 1.0)) * 31.0;
    int i = min(int(floor(x)), 30);
    return mix(cnlm_sheen_albedo[i], cnlm_sheen_albedo[i + 1], x - float(i));
}

vec3 cnlm_sheen_layer(vec3 wo, vec3 wi, vec3 base) {
    float s = max(cnlm_sheen_color.r, max(cnlm_sheen_color.g, cnlm_sheen_color.b));
    float e = max(cnlm_sheen_e(wo.z), cnlm_sheen_e(wi.z));
    return cnlm_sheen_color * cnlm_sheen_dv(wo, wi, cnlm_sheen_alpha) + base * max(1.0 - s * e, 0.0);
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
    f = cnlm_sheen_layer(wo, wi, f);
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
