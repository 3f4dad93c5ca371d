#version 300 es
// Standalone preview shader: one directional light plus a constant ambient term.
// Output: sRGB-encoded colour (linear radiance through the sRGB transfer function),
// for a plain 8-bit default framebuffer.
// cnlmc GLSL backend -- material "frosted_glass"
// phrase: frosted glass
// model: glass + ggx + fresnel exact
// options: fresnel=exact, multiscatter=off, profile=es300, form=both, specialize=on
//
// entry points:
//   vec3 cnlm_bsdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv)
//   vec3 cnlm_bsdf(vec3 n, vec3 v, vec3 l, vec2 uv)      (tangent from cnlm_any_tangent(n))
//   n surface normal, t surface tangent (streak direction of anisotropy, +U of the
//   normal map; bitangent = cross(n, t)), v towards the viewer, l towards the light:
//   unit vectors in any one space. Returns the BRDF f (linear Rec.709 RGB),
//   NOT multiplied by cos(theta_l).
//   vec3 cnlm_btdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv)
//   vec3 cnlm_btdf(vec3 n, vec3 v, vec3 l, vec2 uv)
//   the transmission lobe (Walter 2007) for v and l on opposite sides of n: n points to
//   the outside (index 1), the inside has index cnlm_ior. Radiance transport (includes
//   eta_v^2; f_t(v, l)/eta_v^2 is symmetric), tinted by the base colour, NOT multiplied
//   by |cos(theta_l)|; 0 for same-side pairs and where no microfacet refracts v into l.
// uniforms: (values also in the .glsl.json sidecar)
//   vec3 cnlm_base_color = vec3(0.984, 0.995, 0.995)
//   float cnlm_alpha = 0.25
//   float cnlm_ior = 1.52
//   float cnlm_transmission_depth = 0.01
// samplers: none
precision highp float;
precision highp int;
uniform vec3 cnlm_base_color;
uniform float cnlm_alpha;
uniform float cnlm_ior;
uniform float cnlm_transmission_depth;
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

// Anisotropic GGX pieces shared by the reflection and the transmission lobes
// (Walter 2007; Heitz 2014), alpha = (ax, ay) already clamped to CNLM_ALPHA_MIRROR:
//   D(h) = 1/(pi ax ay q^2), q = hx^2/ax^2 + hy^2/ay^2 + hz^2
//   |w|_a = sqrt(ax^2 wx^2 + ay^2 wy^2 + wz^2)   (the Smith Lambda written without 1/cos)
float cnlm_ggx_d_aniso(vec3 h, vec2 a) {
    vec2 hs = h.xy / a;
    float q = dot(hs, hs) + h.z * h.z;
    return 1.0 / (CNLM_PI * a.x * a.y * q * q);
}

float cnlm_alpha_length(vec3 w, vec2 a) {
    vec2 s = a * w.xy;
    return sqrt(dot(s, s) + w.z * w.z);
}

// Rough dielectric transmission, Walter et al. 2007 eq. 21, GGX with the height-correlated
// Smith G2 = 1/(1 + L(wo) + L(wi)) of the reflection lobe (directions mirrored to z > 0).
// Outside (index 1) is z > 0, inside (index ior) z < 0; eta_o / eta_i index of wo's / wi's side.
//   s = eta_i wi + eta_o wo,  h = -s/|s| flipped to h.z >= 0 (generalized half vector)
//   f_t = |wi.h||wo.h| eta_o^2 (1 - F) D(h) G2 / (|s|^2 |wo.z||wi.z|)      (radiance transport)
//       = |wi.h||wo.h| eta_o^2 (1 - F) D(h) 2 / (|s|^2 (|wi.z| |wo|_a + |wo.z| |wi|_a)):  no 1/cos.
// Returns f_t / (1 - F) and the outside direction's cos against h (for F; the same from both
// sides). 0 for same-side pairs, |cos| < CNLM_COS_EPS, ior = 1 (a delta: wi = -wo) and pairs
// no microfacet can refract (total internal reflection region).
float cnlm_ggx_btdf(vec3 wo, vec3 wi, vec2 alpha, float ior, out float cos_out) {
    cos_out = 0.0;
    if (ior == 1.0 || abs(wo.z) < CNLM_COS_EPS || abs(wi.z) < CNLM_COS_EPS || wo.z * wi.z >= 0.0)
        return 0.0;
    float eta_o = wo.z > 0.0 ? 1.0 : ior;
    float eta_i = wi.z > 0.0 ? 1.0 : ior;
    vec3 s = eta_i * wi + eta_o * wo;
    float s2 = dot(s, s);
    if (s2 <= 0.0) return 0.0;
    vec3 h = -s * inversesqrt(s2);
    if (h.z < 0.0) h = -h;
    float oh = dot(wo, h);
    float ih = dot(wi, h);
    if (oh * wo.z <= 0.0 || ih * wi.z <= 0.0 || h.z <= 0.0) return 0.0;
    cos_out = abs(wo.z > 0.0 ? oh : ih);
    vec2 a = max(alpha, vec2(CNLM_ALPHA_MIRROR));
    float d = cnlm_ggx_d_aniso(h, a);
    float g_over_cos = 2.0 / (abs(wi.z) * cnlm_alpha_length(wo, a) + abs(wo.z) * cnlm_alpha_length(wi, a));
    return abs(oh * ih) * eta_o * eta_o * d * g_over_cos / s2;
}

float cnlm_ggx_btdf(vec3 wo, vec3 wi, float alpha, float ior, out float cos_out) {
    return cnlm_ggx_btdf(wo, wi, vec2(alpha), ior, cos_out);
}

// ---- material frosted_glass: glass + ggx + fresnel exact ----

vec3 cnlm_surface_albedo(vec2 uv) {
    return cnlm_base_color;
}

float cnlm_surface_alpha(vec2 uv) {
    return cnlm_alpha;
}

// The base's Fresnel at cos theta; `outside` is the IOR above the base (1, or the coat's).
vec3 cnlm_base_fresnel(float c, float outside) {
    return vec3(cnlm_fresnel_dielectric(c, cnlm_ior / outside));
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
    spec = cnlm_specular(wo, wi, alpha, outside);
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

// Transmission lobe (Walter 2007) in the local frame: wo and wi on opposite sides of the
// surface (outside z > 0, inside z < 0), radiance transport. The interface is colourless: the
// glass's colour is absorbed along the path inside (cnlm_glass_absorption).
vec3 cnlm_btdf_local(vec3 wo, vec3 wi, vec2 uv) {
    float cos_out;
    float ft = cnlm_ggx_btdf(wo, wi, cnlm_surface_alpha(uv), cnlm_ior, cos_out);
    if (ft == 0.0) return vec3(0.0);
    vec3 f = vec3(ft * (1.0 - cnlm_base_fresnel(cos_out, 1.0)));
    return f;
}

vec3 cnlm_btdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv) {
    vec3 tn = cnlm_any_tangent(n);
    vec3 bn = cross(n, tn);
    vec3 wo = vec3(dot(v, tn), dot(v, bn), dot(v, n));
    vec3 wi = vec3(dot(l, tn), dot(l, bn), dot(l, n));
    return cnlm_btdf_local(wo, wi, uv);
}

vec3 cnlm_btdf(vec3 n, vec3 v, vec3 l, vec2 uv) {
    return cnlm_btdf(n, cnlm_any_tangent(n), v, l, uv);
}

// The transmittance along a path of `path` metres inside the glass (Beer-Lambert): the base
// colour is the transmittance through cnlm_transmission_depth metres.
vec3 cnlm_glass_absorption(float path, vec2 uv) {
    vec3 colour = clamp(cnlm_surface_albedo(uv), 0.0, 1.0);
    return path <= 0.0 ? vec3(1.0) : pow(colour, vec3(path / cnlm_transmission_depth));
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
uniform vec3 cnlm_light_direction;
uniform vec3 cnlm_light_radiance;
uniform vec3 cnlm_ambient_radiance;
// Glass: the length of the light's path through the object, metres (the 10 cm preview ball).
uniform float cnlm_glass_thickness;

out vec4 cnlm_frag_color;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 v = normalize(cnlm_camera_position - v_position);
    vec3 l = normalize(cnlm_light_direction);
    vec3 direct = cnlm_bsdf(n, v_tangent, v, l, v_uv) * cnlm_light_radiance * max(dot(n, l), 0.0);
    // Glass: the light seen through the surface when it is behind it (no refracted
    // environment here; that is the preview's job).
    direct += cnlm_btdf(n, v_tangent, v, l, v_uv) * cnlm_glass_absorption(cnlm_glass_thickness, v_uv)
            * cnlm_light_radiance * max(-dot(n, l), 0.0);
    // Constant ambient: A(v) ~ pi f(v, n) (exact for Lambert; the preview adds IBL later).
    vec3 ambient = cnlm_ambient_radiance * CNLM_PI * cnlm_bsdf(n, v_tangent, v, n, v_uv);
    cnlm_frag_color = vec4(cnlm_linear_to_srgb(direct + ambient), 1.0);
}
