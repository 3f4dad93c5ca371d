// A volume's colour from its base-colour map (docs/subsurface.md "Veins"): the map is the colour the
// eye sees there, as base_color is (the body's thick reflectance c; the lexicon makes them equal).
// Light that leaves at p entered around it, over the diffusion profile's reach: the colour is split
// as a square root between where it leaves (the map at p) and where it entered (the map averaged
// over the profile's scale d = cnlm_sss_profile_scale: the mip level whose texels span d), so the
// veins stay, softened as diffusion softens them. Without a bound map: the uniform cnlm_sss_albedo.
vec3 cnlm_sss_mapped_albedo(vec2 uv, vec3 p) {
    if (!cnlm_map_bound(cnlm_map_base_color)) {
        return cnlm_sss_albedo;
    }
    vec3 d = cnlm_sss_in_units(cnlm_sss_profile_scale);
    float uv_per_unit = length(fwidth(uv)) / max(length(fwidth(p)), 1e-6);
    vec2 size = vec2(textureSize(cnlm_map_base_color, 0));
    float texels = (d.r + d.g + d.b) / 3.0 * uv_per_unit * 0.5 * (size.x + size.y);
    vec3 leaving = texture(cnlm_map_base_color, uv).rgb;
    vec3 entering = textureLod(cnlm_map_base_color, uv, log2(max(texels, 1.0))).rgb;
    return sqrt(max(leaving, vec3(0.0)) * max(entering, vec3(0.0)));
}
