// The beam profile shared by scene lines and HUD lines: a bright Gaussian core that fades to
// exactly zero at the quad's edge, so neighbouring quads never show a seam.
float beam_profile(float dist_px, float half_width_px) {
    float x = dist_px / max(half_width_px, 1e-3);
    float core = exp(-4.0 * x * x);
    return core * (1.0 - smoothstep(0.75, 1.0, x));
}

// Closest point to p on segment a-b, as a parameter t in [0, 1].
float closest_t(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    float len2 = dot(ab, ab);
    return len2 > 1e-12 ? clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
}
