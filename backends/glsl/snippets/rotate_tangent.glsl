// Express a local direction in the frame whose tangent is rotated by phi about n.
vec3 cnlm_rotate_tangent(vec3 w, float phi) {
    float c = cos(phi), s = sin(phi);
    return vec3(c * w.x + s * w.y, -s * w.x + c * w.y, w.z);
}
