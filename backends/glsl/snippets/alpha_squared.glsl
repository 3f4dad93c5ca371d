// Perceptual roughness -> alpha, convention "squared" (alpha = r^2, Burley 2012).
float cnlm_alpha_of(float r) {
    float c = clamp(r, 0.0, 1.0);
    return c * c;
}
