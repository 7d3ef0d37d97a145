#version 450 core
// The rectangle of window pixels [u_rect.xy, u_rect.zw) as two triangles (6 vertices).
uniform ivec4 u_rect;
uniform ivec2 u_viewport;

void main() {
    const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(1, 0), vec2(1, 1),
                                   vec2(0, 1));
    vec2 px = mix(vec2(u_rect.xy), vec2(u_rect.zw), corners[gl_VertexID]);
    gl_Position = vec4(px / vec2(u_viewport) * 2.0 - 1.0, 0.0, 1.0);
}
