// World -> local frame: n = +z, t = +x (t made orthogonal to n), b = cross(n, t).
// A tangent parallel to n (or zero) falls back to cnlm_any_tangent(n).
mat3 cnlm_frame(vec3 n, vec3 t) {
    vec3 tt = t - n * dot(n, t);
    float len2 = dot(tt, tt);
    tt = len2 > 1e-12 ? tt * inversesqrt(len2) : cnlm_any_tangent(n);
    return mat3(tt, cross(n, tt), n);
}

vec3 cnlm_to_local(mat3 frame, vec3 w) {
    return vec3(dot(w, frame[0]), dot(w, frame[1]), dot(w, frame[2]));
}
