#version 450 core
// Filled styles: the canvas (paper, fills, ink) is already display-referred; the HUD lines
// (HDR, from the lines target) go on top by their own strength.
// With the style's ink HUD theme (scene::HudTheme) each HUD line is drawn as ink in its own
// hue, darkened to at most u_ink_luminance (relative luminance), over a paper-toned halo
// u_halo_px wide: text and notices then keep their contrast on light paper and over the fills
// and strokes behind them. Without it, the HUD's tone-mapped colour goes over the paper.
in vec2 v_uv;
layout(binding = TEXTURE_UNIT_CANVAS) uniform sampler2D u_canvas;
layout(binding = TEXTURE_UNIT_LINES) uniform sampler2D u_lines;
uniform bool u_ink;
uniform float u_ink_luminance;
uniform float u_halo_px;
uniform vec3 u_paper;  // display-referred paper tone, the halo's colour
layout(location = 0) out vec4 o_color;

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);
// Eight directions 45 degrees apart (cos, sin of i * pi / 4), as constants: llvmpipe does not
// fold the trigonometry of a loop counter, and this shader runs on every pixel near the HUD.
const float kDiag = 0.70710678;
const vec2 kRing[8] = vec2[](vec2(1.0, 0.0), vec2(kDiag, kDiag), vec2(0.0, 1.0),
                             vec2(-kDiag, kDiag), vec2(-1.0, 0.0), vec2(-kDiag, -kDiag),
                             vec2(0.0, -1.0), vec2(kDiag, -kDiag));

float peak_of(vec2 uv) {
    vec3 hud = textureLod(u_lines, uv, 0.0).rgb;
    return max(max(hud.r, hud.g), hud.b);
}

// The halo: the HUD's strongest coverage on two rings around the pixel (bilinear taps).
// The taps' directions are constants: llvmpipe computed cos and sin of the loop counter per
// pixel (about 5 % of this pass on the classic level at 1280x720; the 16 taps themselves are
// most of its 5 ms over the ~100k pixels of the HUD's tiles).
// Coverage rises with the peak, so the strongest coverage is that of the strongest peak: one
// exp, not sixteen (on llvmpipe this shader runs on every pixel near the HUD).
float halo_coverage(ivec2 p) {
    vec2 size = vec2(textureSize(u_lines, 0));
    vec2 c = (vec2(p) + 0.5) / size;
    float peak = 0.0;
    for (int i = 0; i < 8; ++i) {
        vec2 d = kRing[i] * u_halo_px / size;
        peak = max(peak, peak_of(c + d));
        peak = max(peak, peak_of(c + 0.5 * d));
    }
    return 1.0 - exp(-peak);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 paper = texelFetch(u_canvas, p, 0).rgb;
    vec3 hud = texelFetch(u_lines, p, 0).rgb;
    float peak = max(max(hud.r, hud.g), hud.b);
    float a = 1.0 - exp(-peak);
    if (!u_ink) {
        vec3 hud_colour = peak > 1e-6 ? pow(hud / peak, vec3(1.0 / 2.2)) * 0.8 : vec3(0.0);
        o_color = vec4(mix(paper, hud_colour, a), 1.0);
        return;
    }
    float halo = min(1.0, 2.0 * halo_coverage(p));
    vec3 under = mix(paper, u_paper, max(halo, a));
    vec3 hue = peak > 1e-6 ? hud / peak : vec3(0.0);
    float lum = dot(hue, kLuminance);
    vec3 ink = hue * min(1.0, u_ink_luminance / max(lum, 1e-4));
    // Ink covers fully from a little coverage on: thin text stays dark, not a faint tint.
    float ink_a = min(1.0, 4.0 * a);
    o_color = vec4(mix(under, pow(ink, vec3(1.0 / 2.2)), ink_a), 1.0);
}
