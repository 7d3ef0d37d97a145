#version 450 core
// Phosphor persistence: the picture shown is the brighter of this frame's beam image and the
// previous picture, decayed by the time that has passed (MAME: max(this frame, decayed
// previous frame)). Decay follows elapsed seconds, not frames, so 30, 60 and 144 fps leave
// the same trail.
//   exponential: exp(-t / tau), memoryless: each frame scales by exp(-dt / tau), per channel.
//   power law:   (1 + t / t0)^-p, which depends on how long ago the pixel was lit: alpha keeps
//                that age in seconds, and a frame scales by decay(age + dt) / decay(age).
in vec2 v_uv;
uniform sampler2D u_lines;    // this frame's beam image
uniform sampler2D u_history;  // the previous picture: rgb, a = age (s, power law)
uniform float u_dt;           // seconds since the previous picture (0: the same instant)
uniform int u_power_law;      // 0 exponential, 1 power law
uniform float u_exp_factor;   // exponential: exp(-dt / tau), computed once on the CPU
uniform float u_t0_inv;       // power law: 1 / t0
uniform float u_exponent;     // power law: p
layout(location = 0) out vec4 o_color;

// Below this the phosphor counts as dark, so the history returns to exact zero.
const float kDark = 1.0 / 4096.0;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 beam = texelFetch(u_lines, px, 0).rgb;
    vec4 history = texelFetch(u_history, px, 0);
    vec3 held;
    float age = history.a + u_dt;
    if (u_power_law == 0) {
        held = history.rgb * u_exp_factor;
    } else {
        held = history.rgb * pow((1.0 + history.a * u_t0_inv) / (1.0 + age * u_t0_inv), u_exponent);
    }
    if (max(held.r, max(held.g, held.b)) < kDark) held = vec3(0.0);
    if (u_power_law == 0) {
        o_color = vec4(max(beam, held), 0.0);
    } else {
        // The age belongs to one excitation, so the brighter one wins whole.
        bool fresh = max(beam.r, max(beam.g, beam.b)) >= max(held.r, max(held.g, held.b));
        o_color = fresh ? vec4(beam, 0.0) : vec4(held, age);
    }
}
