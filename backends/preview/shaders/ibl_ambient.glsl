// ---- tier "analytic": constant ambient, A(v) ~ pi f(v, n) * mean radiance ----
uniform vec3 pv_ambient;

vec3 pv_ibl(vec3 ng, vec3 ns, vec3 t, vec3 v, vec2 uv) {
    return pv_ambient * PV_PI * cnlm_bsdf(ng, t, v, ns, uv);
}
