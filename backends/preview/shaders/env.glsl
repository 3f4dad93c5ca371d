// ---- preview: equirectangular environment (Mitsuba envmap convention, +y up) ----
const float PV_PI = 3.14159265358979;
uniform sampler2D pv_env;            // radiance, mip-mapped (box filter), repeat in u
uniform sampler2D pv_env_prefiltered; // GGX-prefiltered: mip level k <-> sqrt(alpha) = k / pv_prefilter_levels
uniform float pv_prefilter_levels;
uniform float pv_env_intensity;

vec2 pv_env_uv(vec3 d) {
    float u = atan(d.x, -d.z) * (0.5 / PV_PI);
    float v = acos(clamp(d.y, -1.0, 1.0)) / PV_PI;
    return vec2(fract(u), v);
}

vec3 pv_env_lod(vec3 d, float lod) {
    return textureLod(pv_env, pv_env_uv(d), lod).rgb * pv_env_intensity;
}

// An orthonormal frame (t, b, n) around n with t as close to `t_hint` as possible.
mat3 pv_frame(vec3 n, vec3 t_hint) {
    vec3 t = t_hint - n * dot(n, t_hint);
    float len2 = dot(t, t);
    t = len2 > 1e-12 ? t * inversesqrt(len2) : cnlm_any_tangent(n);
    return mat3(t, cross(n, t), n);
}
