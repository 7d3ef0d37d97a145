#version 450 core
// Extrudes one HUD segment into a quad, exactly as the scene lines are extruded.
#include "../beam/beam_width.glsl"
#include "../beam/beam_tiles.glsl"

layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 v_color[];
in float v_intensity[];
uniform vec2 u_viewport;
// x: the least half-width (px), y: a gain. Drawn after the bloom on the dark looks, the HUD
// gets no glow on its core; a wider, brighter beam keeps thin text and the radar legible
// (pass_hud.cpp). (0, 1) leaves the beam as the scene's.
uniform vec2 u_hud_beam;
uniform float u_ink_halo_px;  // the ink theme's paper halo past the beam (hud.frag)

noperspective out vec2 g_pixel;
flat out vec2 g_p0;
flat out vec2 g_p1;
flat out vec3 g_color;
flat out vec3 g_beam;  // half-width (px), gain, softness

void main() {
    vec2 s0 = gl_in[0].gl_Position.xy, s1 = gl_in[1].gl_Position.xy;
    vec2 d = s1 - s0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    // HUD keys start high so a HUD line never flickers in step with a scene line.
    BeamShape beam = beam_shape(v_intensity[0], len, 0x80000000u + uint(gl_PrimitiveIDIn));
    beam.half_width = max(beam.half_width, u_hud_beam.x);
    beam.gain *= u_hud_beam.y;
    float h = beam.half_width, r = beam_end_reach(h);  // lengthened ends: beam_ends.glsl
    mark_beam_segment(s0, s1, h, r);
    // The quad reaches the halo too (the ink composite's reach covers it past the marks).
    float qh = h + u_ink_halo_px, qr = r + u_ink_halo_px;
    vec2 corners[4] = vec2[4](s0 - dir * qr - nrm * qh, s0 - dir * qr + nrm * qh,
                              s1 + dir * qr - nrm * qh, s1 + dir * qr + nrm * qh);
    for (int k = 0; k < 4; ++k) {
        g_pixel = corners[k];
        g_p0 = s0;
        g_p1 = s1;
        g_color = v_color[0];
        g_beam = vec3(beam.half_width, beam.gain, beam.softness);
        gl_Position = vec4(corners[k] / u_viewport * 2.0 - 1.0, 0.0, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
