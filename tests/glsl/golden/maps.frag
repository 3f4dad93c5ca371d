#version 330 core
// Standalone preview shader: one directional light plus a constant ambient term.
// Output: sRGB-encoded colour (linear radiance through the sRGB transfer function),
// for a plain 8-bit default framebuffer.
// cnlmc GLSL backend -- material "rusty_iron"
// phrase: rusty iron
// model: conductor + ggx + fresnel exact + maps: base_color, roughness, mask
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
//   vec3 cnlm_eta = vec3(2.9227, 2.9197, 2.5463)
//   vec3 cnlm_k = vec3(3.0773, 2.9373, 2.75)
// samplers: (bind baked maps; see the sidecar)
//   sampler2D cnlm_map_base_color  role=base_color colour_space=srgb: RGB albedo/tint; upload as an sRGB texture (GL_SRGB8[_ALPHA8]) so texture() returns linear
//   sampler2D cnlm_map_roughness  role=roughness colour_space=linear: perceptual roughness in the red channel
//   sampler2D cnlm_map_mask  role=mask colour_space=linear: coverage in the red channel: blends the surface towards a Lambert lobe of the base colour
uniform vec3 cnlm_eta = vec3(2.9227, 2.9197, 2.5463);
uniform vec3 cnlm_k = vec3(3.0773, 2.9373, 2.75);
uniform sampler2D cnlm_map_base_color;
uniform sampler2D cnlm_map_roughness;
uniform sampler2D cnlm_map_mask;
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

// A sampler with no texture bound reads a 1x1 black texture (0, 0, 0, 1). Baked maps are at least
// 8x8, so a texture of 1 texel is "not bound": the shader then uses the IR's uniform value instead of
// black (a black normal or roughness map would remove the highlight).
bool cnlm_map_bound(sampler2D map) {
    return textureSize(map, 0).x > 1;
}

// Perceptual roughness -> alpha, convention "squared" (alpha = r^2, Burley 2012).
float cnlm_alpha_of(float r) {
    float c = clamp(r, 0.0, 1.0);
    return c * c;
}

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

// Lambert: f = albedo / pi (0 below the horizon).
vec3 cnlm_lambert(vec3 wo, vec3 wi, vec3 albedo) {
    return cnlm_both_upper(wo, wi) ? albedo / CNLM_PI : vec3(0.0);
}

// ---- material rusty_iron: conductor + ggx + fresnel exact + maps: base_color, roughness, mask ----

vec3 cnlm_surface_albedo(vec2 uv) {
    if (!cnlm_map_bound(cnlm_map_base_color)) {
        return vec3(0.412, 0.398, 0.384);  // the IR's base colour where no map is bound
    }
    return texture(cnlm_map_base_color, uv).rgb;
}

float cnlm_surface_alpha(vec2 uv) {
    float r = cnlm_map_bound(cnlm_map_roughness) ? texture(cnlm_map_roughness, uv).r : 0.6;
    float a = cnlm_alpha_of(r);
    return clamp(a, CNLM_ALPHA_MIRROR, 1.0);
}

// The base's Fresnel at cos theta; `outside` is the IOR above the base (1, or the coat's).
vec3 cnlm_base_fresnel(float c, float outside) {
    return cnlm_fresnel_conductor(c, cnlm_eta / outside, cnlm_k / outside);
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
    f = mix(f, cnlm_lambert(wo, wi, albedo), cnlm_map_bound(cnlm_map_mask) ? clamp(texture(cnlm_map_mask, uv).r, 0.0, 1.0) : 0.0);
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
