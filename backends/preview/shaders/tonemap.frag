#version 330 core
// cnlmc preview, the last pass: edge filter, background, exposure, ACES filmic curve
// (Narkowicz 2015 fit), sRGB transfer function.
// Edge filter (pv_edge_aa = 1, for targets without MSAA): where the compressed luma or the
// coverage of a 4-neighbour differs from this pixel's by more than a threshold, the object
// layer (premultiplied, linear) becomes the tent blend 1/2 centre + 1/8 each neighbour; the
// background is then composited under it with the filtered coverage, as an MSAA resolve would.
// Background (pv_background = 1): background.frag's quarter-resolution image of the blurred
// environment, upsampled bilinearly where the object does not cover the pixel entirely.
// PV_BACKGROUND_ONLY (defined by the renderer for the frame outside the object's rectangle):
// the background alone, without the object layer's reads.
in vec2 v_uv;
in vec2 v_ndc;
uniform sampler2D pv_hdr;
uniform sampler2D pv_background_image;
uniform float pv_exposure;
uniform int pv_curve;      // 0: ACES fit, 1: clamp (linear)
uniform int pv_edge_aa;
uniform int pv_background;
out vec4 pv_color;

const float PV_EDGE_THRESHOLD = 0.04;

vec3 pv_aces(vec3 x) {
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// sRGB encoding. Above the linear toe, 1.055 x^(1/2.4) - 0.055 is evaluated as a sum of
// x^(1/2), x^(1/4), x^(1/8) and x (square roots, coefficients fitted in numpy by reweighted
// least squares on [0.0031308, 1]): largest error 3.1e-5, 0.008 of an 8-bit step. llvmpipe
// computes pow() as exp2(log2()) in software: this halves the cost of the tone-map pass.
vec3 pv_srgb(vec3 c) {
    vec3 x = clamp(c, 0.0, 1.0);
    vec3 r2 = sqrt(x), r4 = sqrt(r2), r8 = sqrt(r4);
    vec3 curve = -0.00406562 + 0.65398271 * r2 + 0.68872019 * r4 - 0.31848075 * r8 - 0.02018794 * x;
    return mix(12.92 * x, curve, step(vec3(0.0031308), x));
}

float pv_key(vec4 c) {
    float l = dot(max(c.rgb, 0.0), vec3(0.2126, 0.7152, 0.0722)) * pv_exposure;
    return l / (1.0 + l) + c.a;
}

vec4 pv_fetch(ivec2 p, ivec2 hi) {
    return texelFetch(pv_hdr, clamp(p, ivec2(0), hi), 0);
}

vec4 pv_object(ivec2 p) {
    vec4 c = texelFetch(pv_hdr, p, 0);
    if (pv_edge_aa == 0) return c;
    ivec2 hi = textureSize(pv_hdr, 0) - 1;
    vec4 l = pv_fetch(p + ivec2(-1, 0), hi), r = pv_fetch(p + ivec2(1, 0), hi);
    vec4 d = pv_fetch(p + ivec2(0, -1), hi), u = pv_fetch(p + ivec2(0, 1), hi);
    float k = pv_key(c);
    float contrast = max(max(abs(pv_key(l) - k), abs(pv_key(r) - k)), max(abs(pv_key(d) - k), abs(pv_key(u) - k)));
    return contrast > PV_EDGE_THRESHOLD ? 0.5 * c + 0.125 * (l + r + d + u) : c;
}

void main() {
#ifdef PV_BACKGROUND_ONLY
    vec4 c = vec4(0.0);          // outside the rectangle the object was drawn in: nothing there
#else
    vec4 c = pv_object(ivec2(gl_FragCoord.xy));
#endif
    c.a = clamp(c.a, 0.0, 1.0);
    if (pv_background != 0) {
        if (c.a < 1.0) c.rgb += (1.0 - c.a) * texture(pv_background_image, v_uv).rgb;
        c.a = 1.0;
    }
    vec3 x = c.rgb * pv_exposure;
    vec3 mapped = pv_curve == 0 ? pv_aces(x) : clamp(x, 0.0, 1.0);
    pv_color = vec4(pv_srgb(mapped), c.a);
}
