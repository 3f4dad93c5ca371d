// Perceptual roughness -> alpha, convention "linear" (alpha = r, the paper's m).
float cnlm_alpha_of(float r) {
    return clamp(r, 0.0, 1.0);
}
