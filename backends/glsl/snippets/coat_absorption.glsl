// Coat absorption along the refracted paths: color^(thickness (1/cos o' + 1/cos i')/2),
// written as exp(log(color) x) so that thickness 0 gives exactly 1 even for color 0.
vec3 cnlm_coat_absorption(vec3 wo_in, vec3 wi_in, vec3 color, float thickness) {
    float x = 0.5 * thickness * (1.0 / max(wo_in.z, 1e-12) + 1.0 / max(wi_in.z, 1e-12));
    return exp(log(max(clamp(color, 0.0, 1.0), vec3(1e-30))) * x);
}
