// Phosphor persistence: the picture shown is the brighter of this frame's beam image and the
// previous picture, decayed by the time that has passed (MAME: max(this frame, decayed
// previous frame)). Decay follows elapsed seconds, not frames, so 30, 60 and 144 fps leave
// the same trail. The composite computes it per pixel and stores the new picture; the
// bloom's first downsample computes it per filtered sample for the glow (pass_phosphor.cpp).
//   exponential: exp(-t / tau), memoryless: each frame scales by exp(-dt / tau), per channel.
//   power law:   (1 + t / t0)^-p, which depends on how long ago the pixel was lit: alpha keeps
//                that age in seconds, and a frame scales by decay(age + dt) / decay(age).
uniform float u_dt;           // seconds since the previous picture (0: the same instant)
// POWER_LAW (defined by the program, 0 or 1) picks the decay at compile time.
uniform float u_exp_factor;   // exponential: exp(-dt / tau), computed once on the CPU
uniform float u_t0_inv;       // power law: 1 / t0
uniform float u_exponent;     // power law: p

// Below this the phosphor counts as dark, so the history returns to exact zero.
const float kDark = 1.0 / 4096.0;

float phosphor_peak(vec3 c) { return max(c.r, max(c.g, c.b)); }

// The new picture (rgb, a = age for the power law) from this frame's beam and the last one.
vec4 phosphor_picture(vec3 beam, vec4 history) {
    vec3 held;
    float age = history.a + u_dt;
    if (POWER_LAW == 0) {
        held = history.rgb * u_exp_factor;
    } else {
        held = history.rgb * pow((1.0 + history.a * u_t0_inv) / (1.0 + age * u_t0_inv), u_exponent);
    }
    if (phosphor_peak(held) < kDark) held = vec3(0.0);
    if (POWER_LAW == 0) return vec4(max(beam, held), 0.0);
    // The age belongs to one excitation, so the brighter one wins whole.
    return phosphor_peak(beam) >= phosphor_peak(held) ? vec4(beam, 0.0) : vec4(held, age);
}
