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

layout(location = 0) out vec4 o_color;

void main() {
    float t = closest_t(g_pixel, g_p0, g_p1);
    float dist = beam_distance(g_pixel, g_p0, g_p1, mix(g_p0, g_p1, t), g_beam.x);
    if (dist >= g_beam.x) discard;
    o_color = vec4(g_color * (g_beam.y * beam_profile(dist, g_beam.x, g_beam.z)), 1.0);
#ifdef LIT_TILES
    if (max(o_color.r, max(o_color.g, o_color.b)) > 0.0) {
        ivec2 px = ivec2(gl_FragCoord.xy);
        mark_pixels(px, px);
    }
#endif
}
