#version 450 core
// HUD lines: HUD units (origin at the centre, y up, 1 unit = half the screen height).
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec3 a_color;      // colour * intensity
layout(location = 2) in float a_intensity;  // for the beam's width (beam_width.glsl)

uniform vec2 u_viewport;

out vec3 v_color;
out float v_intensity;

void main() {
    vec2 px = u_viewport * 0.5 + a_position * (u_viewport.y * 0.5);
    v_color = a_color;
    v_intensity = a_intensity;
    gl_Position = vec4(px, 0.0, 1.0);  // window pixels; the geometry shader extrudes
}
