// ---- preview: deterministic sample sequences and importance sampling ----
uint pv_hash(uint x) {
    x ^= x >> 16u; x *= 0x7feb352du; x ^= x >> 15u; x *= 0x846ca68bu; x ^= x >> 16u;
    return x;
}

float pv_radical_inverse(uint bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10;
}

// Hammersley point i of n, rotated by `shift` (Cranley-Patterson) modulo 1.
vec2 pv_hammersley(int i, int n, vec2 shift) {
    return fract(vec2((float(i) + 0.5) / float(n), pv_radical_inverse(uint(i))) + shift);
}

// Cosine-weighted hemisphere direction (local frame, z up) and its pdf.
vec3 pv_sample_cosine(vec2 xi) {
    float r = sqrt(xi.x), phi = 2.0 * PV_PI * xi.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - xi.x, 0.0)));
}

float pv_pdf_cosine(vec3 l) { return max(l.z, 0.0) / PV_PI; }

// Isotropic GGX visible-normal sampling (Heitz 2018) of a microfacet normal for view v (z up).
vec3 pv_sample_vndf(vec3 v, float a, vec2 xi) {
    vec3 vh = normalize(vec3(a * v.x, a * v.y, v.z));
    float len2 = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = len2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(xi.x), phi = 2.0 * PV_PI * xi.y;
    float p1 = r * cos(phi), p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0)) * vh;
    return normalize(vec3(a * nh.x, a * nh.y, max(nh.z, 0.0)));
}

// pdf of the reflected direction l under VNDF sampling: D(h) G1(v) / (4 v.z).
float pv_pdf_vndf(vec3 v, vec3 l, float a) {
    if (l.z <= 0.0 || v.z <= 0.0) return 0.0;
    vec3 h = normalize(v + l);
    float q = (h.x * h.x + h.y * h.y) / (a * a) + h.z * h.z;
    float d = 1.0 / (PV_PI * a * a * q * q);
    float lam = sqrt(a * a * (1.0 - v.z * v.z) + v.z * v.z);
    float g1 = 2.0 * v.z / (v.z + lam);
    return d * g1 / (4.0 * v.z);
}
