#version 330 core
// cnlmc preview: GGX prefiltered environment for the split-sum tier (Karis 2013), n = v = r,
// with filtered importance sampling (Krivanek & Colbert 2008) from the box-filtered mip chain.
in vec2 v_uv;
uniform sampler2D pv_env;
uniform float pv_alpha;
uniform int pv_samples;
uniform vec2 pv_env_size;
uniform int pv_cosine;     // 1: cosine lobe around n (irradiance / pi) instead of GGX
out vec4 pv_color;
const float PV_PI = 3.14159265358979;

float pv_radical_inverse(uint bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10;
}

vec3 pv_dir(vec2 uv) {
    float phi = uv.x * 2.0 * PV_PI, theta = uv.y * PV_PI;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}

vec2 pv_uv(vec3 d) {
    return vec2(fract(atan(d.x, -d.z) * (0.5 / PV_PI)), acos(clamp(d.y, -1.0, 1.0)) / PV_PI);
}

void main() {
    vec3 n = pv_dir(v_uv);
    vec3 up = abs(n.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(up, n)), b = cross(n, t);
    float a = max(pv_alpha, 1e-3), a2 = a * a;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int i = 0; i < pv_samples; ++i) {
        vec2 xi = vec2((float(i) + 0.5) / float(pv_samples), pv_radical_inverse(uint(i)));
        float cos_h = sqrt((1.0 - xi.x) / (1.0 + (a2 - 1.0) * xi.x));
        float sin_h = sqrt(max(1.0 - cos_h * cos_h, 0.0));
        float phi = 2.0 * PV_PI * xi.y;
        vec3 h = vec3(sin_h * cos(phi), sin_h * sin(phi), cos_h);
        vec3 l = 2.0 * h.z * h - vec3(0.0, 0.0, 1.0);
        float denom = cos_h * cos_h * (a2 - 1.0) + 1.0;
        float pdf = a2 / (PV_PI * denom * denom) / 4.0;      // n = v: pdf(l) = D(h) cos_h / (4 h.l)
        if (pv_cosine == 1) {                                // cosine-distributed l, weight 1
            float cos_l = sqrt(1.0 - xi.x);
            l = vec3(sqrt(xi.x) * cos(phi), sqrt(xi.x) * sin(phi), cos_l);
            pdf = cos_l / PV_PI;
        }
        if (l.z <= 0.0) continue;
        vec3 w = t * l.x + b * l.y + n * l.z;
        float texel = 4.0 * PV_PI / (pv_env_size.x * pv_env_size.y);
        float lod = max(0.5 * log2((1.0 / (float(pv_samples) * pdf)) / texel) + 1.0, 0.0);
        float w_l = pv_cosine == 1 ? 1.0 : l.z;
        sum += textureLod(pv_env, pv_uv(w), lod).rgb * w_l;
        weight += w_l;
    }
    pv_color = vec4(sum / max(weight, 1e-6), 1.0);
}
