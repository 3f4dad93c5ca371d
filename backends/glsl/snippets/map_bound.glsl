// A sampler with no texture bound reads a 1x1 black texture (0, 0, 0, 1). Baked maps are at least
// 8x8, so a texture of 1 texel is "not bound": the shader then uses the IR's uniform value instead of
// black (a black normal or roughness map would remove the highlight).
bool cnlm_map_bound(sampler2D map) {
    return textureSize(map, 0).x > 1;
}
