// Subsurface: light that enters the body, scatters and leaves (docs/subsurface.md, docs/glsl.md
// "Subsurface"). The one source of this term: the GLSL target's library and the preview's shader
// (backends/preview/shaders/subsurface.glsl.j2 calls cnlm_subsurface) both use this code.
// cnlm_bsdf is the boundary alone (a volume: its specular lobe, base colour black; a thin sheet:
// its front, base colour x (1 - max T)); the body adds the radiance
//   t_in (1 - F(n.v)) x [ R(e_n) (D(n.l, d / r) E_light / pi + E_front / pi)       front: reflected
//                         + T(e_n) E_back / pi + T(e_l) max(-n.l, 0) E_light / pi ] back: transmitted
// the body a Kubelka-Munk slab whose reflectance when thick is c = cnlm_sss_albedo (the dipole's total
// diffuse reflectance of the medium behind its boundary): R(e) = c (1 - e^2) / (1 - c^2 e^2) comes
// back, T(e) = (1 - c^2) e / (1 - c^2 e^2) crosses (session 9 had c (1 - e) and c e: a backlit body
// let 2-5x too much through), e = exp(-d / l_d), l_d = cnlm_sss_mfp (the diffuse mean free path
// 1/sigma_tr) per channel; t_in = cnlm_sss_entry (the boundary's mean diffuse transmittance where
// light enters: Jensen et al. 2001's BSSRDF has a Fresnel transmittance at both ends); d = the path
// through the body, along -n (e_n) and towards the light (e_l): the chord through the sphere of the
// surface's own curvature radius touching it here (a thin part is thin, a thick part thick), at most the chord to the object's bounding sphere
// (cnlm_sss_centre, cnlm_sss_radius). D is the light's cosine pre-integrated over the
// Christensen-Burley profile around the curvature radius r (Penner 2011): the table cnlm_sss_lut
// (rows cos(theta) in [-1, 1], columns u = rho / (1 + rho) in [0, cnlm_sss_lut_u_max], rho = d / r,
// d = cnlm_sss_profile_scale), read with texelFetch and interpolated bilinearly here.
// A thin wall (cnlm_sss_thin == 1) transmits T_d = cnlm_sss_wall_through (the Kubelka-Munk slab of
// its medium at its thickness) of the light behind it; a closed shell's cavity (cnlm_sss_cavity).
// Lengths: cnlm_sss_mfp and cnlm_sss_profile_scale in metres, positions in scene units of
// cnlm_sss_unit metres each.

// The length l (metres) in scene units, at least 1e-6.
vec3 cnlm_sss_in_units(vec3 l) {
    return max(l / cnlm_sss_unit, vec3(1e-6));
}

// Distance from p along the unit direction d to where it leaves the bounding sphere.
float cnlm_sss_chord(vec3 p, vec3 d) {
    vec3 o = p - cnlm_sss_centre;
    float b = dot(o, d);
    float c = dot(o, o) - cnlm_sss_radius * cnlm_sss_radius;
    return max(-b + sqrt(max(b * b - c, 0.0)), 0.0);
}

// Mean curvature magnitude 1/r from screen-space derivatives of the normal and the position
// (fragment shaders only; any other estimate of 1/r in scene units will do).
float cnlm_sss_curvature(vec3 n, vec3 p) {
    return length(fwidth(n)) / max(length(fwidth(p)), 1e-6);
}

// The path from p along d (into the body: d.n < 0) to where it leaves: through the osculating sphere
// of radius r = 1/curvature (centre p - r n: t = -2 r (d.n)), no longer than through the bounding sphere.
float cnlm_sss_path(vec3 p, vec3 n, vec3 d, float curvature) {
    float local = -2.0 * dot(d, n) / max(curvature, 1e-6);
    return min(max(local, 0.0), cnlm_sss_chord(p, d));
}

// exp(-d / l_d) per channel: d the path from p along the direction `d` through the body.
vec3 cnlm_sss_crossing(vec3 p, vec3 n, vec3 d, float curvature) {
    return exp(-cnlm_sss_path(p, n, d, curvature) / cnlm_sss_in_units(cnlm_sss_mfp));
}

// The body as a Kubelka-Munk slab whose infinitely thick reflectance is the IR's colour c, of optical
// depth d / l_d (e = exp(-d / l_d), cnlm_sss_crossing): what it reflects (R) and what it lets through (T)
//   R = c (1 - e^2) / (1 - c^2 e^2),  T = (1 - c^2) e / (1 - c^2 e^2)      (R + T <= 1; thick: R = c)
// c the body's colour where the light leaves: cnlm_sss_albedo, or the base-colour map's there
// (cnlm_sss_mapped_albedo, docs/subsurface.md "Veins").
vec3 cnlm_sss_slab_denominator(vec3 e, vec3 c) {
    return max(1.0 - c * c * e * e, vec3(1e-4));
}

vec3 cnlm_sss_slab_reflected(vec3 e, vec3 c) {
    return c * (1.0 - e * e) / cnlm_sss_slab_denominator(e, c);
}

vec3 cnlm_sss_slab_through(vec3 e, vec3 c) {
    return (1.0 - c * c) * e / cnlm_sss_slab_denominator(e, c);
}

float cnlm_sss_exit(vec3 n, vec3 v) {
    float m = 1.0 - clamp(dot(n, v), 0.0, 1.0);
    return 1.0 - (cnlm_sss_f0 + (1.0 - cnlm_sss_f0) * m * m * m * m * m);
}

// The pre-integrated table: the sampler cnlm_sss_lut, or (maps=none: no image) the const array
// cnlm_sss_lut_values the library declares behind CNLM_SSS_LUT_CONST (a const array is not a uniform).
#ifdef CNLM_SSS_LUT_CONST
ivec2 cnlm_sss_lut_size() {
    return ivec2(CNLM_SSS_LUT_COLUMNS, CNLM_SSS_LUT_ROWS);
}

float cnlm_sss_lut_at(ivec2 texel) {
    return cnlm_sss_lut_values[texel.y * CNLM_SSS_LUT_COLUMNS + texel.x];
}
#else
ivec2 cnlm_sss_lut_size() {
    return textureSize(cnlm_sss_lut, 0);
}

float cnlm_sss_lut_at(ivec2 texel) {
    return texelFetch(cnlm_sss_lut, texel, 0).r;
}
#endif

// The table, bilinear (subsurface_profile.PreintegratedTable.lookup does the same).
float cnlm_sss_preintegrated(float nl, float rho) {
    ivec2 steps = cnlm_sss_lut_size();  // (rho steps, cos steps)
    float row = (clamp(nl, -1.0, 1.0) + 1.0) * 0.5 * float(steps.y - 1);
    float col = clamp(rho / (1.0 + rho) / cnlm_sss_lut_u_max, 0.0, 1.0) * float(steps.x - 1);
    int r0 = min(int(row), steps.y - 2);
    int c0 = min(int(col), steps.x - 2);
    float fr = row - float(r0), fc = col - float(c0);
    float top = mix(cnlm_sss_lut_at(ivec2(c0, r0)), cnlm_sss_lut_at(ivec2(c0 + 1, r0)), fc);
    float bottom = mix(cnlm_sss_lut_at(ivec2(c0, r0 + 1)), cnlm_sss_lut_at(ivec2(c0 + 1, r0 + 1)), fc);
    return mix(top, bottom, fr);
}

// The light's cosine spread by the profile over the curvature radius, per channel.
vec3 cnlm_sss_diffused(float curvature, float nl) {
    vec3 rho = cnlm_sss_in_units(cnlm_sss_profile_scale) * curvature;
    return vec3(cnlm_sss_preintegrated(nl, rho.r), cnlm_sss_preintegrated(nl, rho.g), cnlm_sss_preintegrated(nl, rho.b));
}

// A thin wall: what it transmits diffusely (T_d) of the light behind it; its front is cnlm_bsdf's.
// A closed shell (a lantern, a leaf-skinned ball): light crosses a wall into the cavity, where it is
// uniform (a sphere's: any diffuse source on it lights its inside evenly; a convex shell's
// approximately), comes back from the walls (cnlm_sss_wall_reflect, R_in) and leaves through them:
// radiance out = T x T E_out / (pi (1 - R_in)), E_out the irradiance on the outside averaged over
// the shell: the mean of the light on both sides and a quarter of the light's (a convex body's
// cross-section over its area, Cauchy). Energy: T / (1 - R_in) <= 1 as R_in + T <= 1.
vec3 cnlm_sss_cavity(vec3 light, vec3 front, vec3 back) {
    vec3 gain = cnlm_sss_wall_through / max(1.0 - cnlm_sss_wall_reflect, vec3(1e-4));
    return cnlm_sss_wall_through * gain * (0.5 * (front + back) + 0.25 * light / CNLM_PI);
}

vec3 cnlm_sss_thin_wall(vec3 n, vec3 v, vec3 l, vec3 light, vec3 front, vec3 back) {
    vec3 through = cnlm_sss_closed == 1
        ? cnlm_sss_cavity(light, front, back)
        : cnlm_sss_wall_through * (back + max(-dot(n, l), 0.0) * light / CNLM_PI);
    return cnlm_sss_exit(n, v) * through;
}

// A thick volume: what enters near here comes back (1 - T_n) or crosses the body (T_n, T_l); `albedo`
// its colour c here (at most 0.9999: a lossless body has no finite answer).
vec3 cnlm_sss_volume(vec3 p, vec3 n, vec3 v, vec3 l, vec3 light, vec3 front, vec3 back, float curvature, vec3 albedo) {
    vec3 c = min(albedo, vec3(0.9999));
    float nl = dot(n, l);
    vec3 through_n = cnlm_sss_crossing(p, n, -n, curvature);
    vec3 through_l = cnlm_sss_crossing(p, n, l, curvature);
    vec3 reflected = cnlm_sss_slab_reflected(through_n, c) * (cnlm_sss_diffused(curvature, nl) * light / CNLM_PI + front);
    vec3 crossed = cnlm_sss_slab_through(through_n, c) * back + cnlm_sss_slab_through(through_l, c) * max(-nl, 0.0) * light / CNLM_PI;
    return cnlm_sss_entry * cnlm_sss_exit(n, v) * (reflected + crossed);
}

// The body's radiance with its colour `albedo` at p (a thick volume's; a thin wall has none of its own).
vec3 cnlm_sss_body(vec3 p, vec3 n, vec3 v, vec3 l, vec3 light, vec3 front, vec3 back, float curvature, vec3 albedo) {
    return cnlm_sss_thin == 1
        ? cnlm_sss_thin_wall(n, v, l, light, front, back)
        : cnlm_sss_volume(p, n, v, l, light, front, back, curvature, albedo);
}

// The body's radiance towards v at p (scene units), n the unit shading normal, l the unit direction
// towards the light, `light` its irradiance at normal incidence (RGB), `front` and `back` the
// environment's irradiance / pi around n and around -n (a uniform ambient radiance L: both L),
// `curvature` 1/r in 1/scene units (cnlm_sss_curvature(n, p) in a fragment shader). The body's colour
// is the uniform cnlm_sss_albedo; the library's overload with a last argument `vec2 uv` colours a
// volume by its base-colour map where the material has one (the veins of marble).
vec3 cnlm_subsurface(vec3 p, vec3 n, vec3 v, vec3 l, vec3 light, vec3 front, vec3 back, float curvature) {
    return cnlm_sss_body(p, n, v, l, light, front, back, curvature, cnlm_sss_albedo);
}
