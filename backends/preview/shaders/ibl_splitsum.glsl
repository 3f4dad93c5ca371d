// ---- tier "splitsum": Karis 2013. Specular = prefiltered radiance at the mirror direction
// times (F0 A + B) from the GGX LUT; diffuse = SH irradiance times the diffuse albedo.
// Lobes come from the adapter's pv_split_* (per model); anisotropy uses sqrt(ax ay).
uniform sampler2D pv_brdf_lut;     // (A, B) by (cos theta_v, sqrt(alpha))

vec3 pv_prefiltered(vec3 r, float alpha) {
    float lod = sqrt(clamp(alpha, 0.0, 1.0)) * pv_prefilter_levels;
    return textureLod(pv_env_prefiltered, pv_env_uv(r), lod).rgb * pv_env_intensity;
}

vec2 pv_lut(float nv, float alpha) {
    return texture(pv_brdf_lut, vec2(nv, sqrt(clamp(alpha, 0.0, 1.0)))).rg;
}

{% include "split.glsl.j2" %}

vec3 pv_ibl(vec3 ng, vec3 ns, vec3 t, vec3 v, vec2 uv) {
    float nv = clamp(dot(ns, v), 1e-4, 1.0);
    vec3 r = reflect(-v, ns);
    return pv_split(ns, r, nv, uv);
}
