#version 450 core
#include "../beam/beam.glsl"
#ifdef LIT_TILES
// Drawn after the bloom (render/beam/pass_hud.cpp), each lit fragment marks its lit tile for
// the sparse composite, exactly as the bloom's first downsample marks the scene's light.
#include "../beam/lit_tiles.glsl"
#endif

noperspective in vec2 g_pixel;
flat in vec2 g_p0;
flat in vec2 g_p1;
flat in vec3 g_color;
flat in vec3 g_beam;  // half-width (px), gain, softness (beam_width.glsl)
// The ink HUD theme's paper halo (scene::HudTheme::halo_px; 0 for the glowing theme): alpha
// holds the line's coverage that far out, so the ink composite reads its halo in one fetch
// (pass_hud.cpp blends alpha by MAX: the strongest line's halo).
uniform float u_ink_halo_px;

layout(location = 0) out vec4 o_color;

// The halo's strength from a line's peak value: full from a peak of ln 2 on, so that thin
// text keeps a solid paper rim (shaders/styles/ink_composite.frag lays it under the ink).
float ink_halo(float peak) {
    return min(1.0, 2.0 * (1.0 - exp(-peak)));
}

void main() {
    float t = closest_t(g_pixel, g_p0, g_p1);
    float dist = beam_distance(g_pixel, g_p0, g_p1, mix(g_p0, g_p1, t), g_beam.x);
    if (dist >= g_beam.x + u_ink_halo_px) discard;
    float core = dist < g_beam.x ? g_beam.y * beam_profile(dist, g_beam.x, g_beam.z) : 0.0;
    float alpha = 1.0;
    if (u_ink_halo_px > 0.0) {
        // The line's peak at the nearest point within the halo's reach: the HUD dilated by a
        // disc of radius u_ink_halo_px.
        float near = max(dist - u_ink_halo_px, 0.0);
        float peak = max(g_color.r, max(g_color.g, g_color.b)) * g_beam.y *
                     beam_profile(near, g_beam.x, g_beam.z);
        alpha = ink_halo(peak);
    }
    o_color = vec4(g_color * core, alpha);
#ifdef LIT_TILES
    if (max(o_color.r, max(o_color.g, o_color.b)) > 0.0) {
        ivec2 px = ivec2(gl_FragCoord.xy);
        mark_pixels(px, px);
    }
#endif
}
