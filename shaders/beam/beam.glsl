// The beam profile shared by scene lines and HUD lines: a bright Gaussian core that fades to
// exactly zero at the quad's edge, so neighbouring quads never show a seam.
// `softness` below 1 flattens the core (an overdriven, defocused spot; beam_width.glsl).
#include "beam_ends.glsl"

float beam_profile(float dist_px, float half_width_px, float softness) {
    float x = dist_px / max(half_width_px, 1e-3);
    float core = exp2(-5.77078016 * softness * x * x);  // exp(-4 softness x^2)
    return core * (1.0 - smoothstep(0.75, 1.0, x));
}

float beam_profile(float dist_px, float half_width_px) { return beam_profile(dist_px, half_width_px, 1.0); }

// Closest point to p on segment a-b, as a parameter t in [0, 1].
float closest_t(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    float len2 = dot(ab, ab);
    return len2 > 1e-12 ? clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
}
