// ---- tier "splitsum": Karis 2013, specialized per material. Specular = the environment
// prefiltered for the lobe's alpha, looked up where the lobe's first moment points (a rough
// lobe: a mixture of two prefiltered kernels fitted to its shape per cos theta_v), times the
// lobe's own directional albedo; diffuse = cosine-prefiltered irradiance likewise
// (split.glsl.j2). Anisotropy uses sqrt(ax ay).

vec3 pv_prefiltered(vec3 r, float alpha) {
    float lod = sqrt(clamp(alpha, 0.0, 1.0)) * pv_prefilter_levels;
    return textureLod(pv_env_prefiltered, pv_env_uv(r), lod).rgb * pv_env_intensity;
}

{% include "split.glsl.j2" %}

vec3 pv_ibl(vec3 ng, vec3 ns, vec3 t, vec3 v, vec2 uv) {
    float nv = clamp(dot(ns, v), 1e-4, 1.0);
    return pv_split(ns, v, nv, uv);
}
