// Tangent-space normal map (OpenGL convention, +Y up the image; stored as n * 0.5 + 0.5).
// Bitangent = cross(n, t). An unbound map, or a texel pointing below the surface, keeps n.
vec3 cnlm_perturb_normal(vec3 n, vec3 t, vec2 uv) {
    vec3 m = texture(cnlm_map_normal, uv).xyz * 2.0 - 1.0;
    if (!cnlm_map_bound(cnlm_map_normal) || m.z <= 0.0) {
        return n;
    }
    mat3 frame = cnlm_frame(n, t);
    vec3 p = frame * m;
    float len2 = dot(p, p);
    return len2 > 0.0 ? p * inversesqrt(len2) : n;
}
