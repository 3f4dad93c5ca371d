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
