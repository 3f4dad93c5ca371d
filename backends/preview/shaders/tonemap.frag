#version 330 core
// cnlmc preview: exposure, ACES filmic curve (Narkowicz 2015 fit), sRGB transfer function.
in vec2 v_uv;
uniform sampler2D pv_hdr;
uniform float pv_exposure;
uniform int pv_curve;      // 0: ACES fit, 1: clamp (linear)
out vec4 pv_color;

vec3 pv_aces(vec3 x) {
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 pv_srgb(vec3 c) {
    vec3 x = clamp(c, 0.0, 1.0);
    return mix(12.92 * x, 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), x));
}

void main() {
    vec4 hdr = texture(pv_hdr, v_uv);
    vec3 x = hdr.rgb * pv_exposure;
    vec3 mapped = pv_curve == 0 ? pv_aces(x) : clamp(x, 0.0, 1.0);
    pv_color = vec4(pv_srgb(mapped), clamp(hdr.a, 0.0, 1.0));
}
