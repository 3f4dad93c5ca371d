// A unit tangent orthogonal to n, continuous except at n.z = -1
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
vec3 cnlm_any_tangent(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
}
