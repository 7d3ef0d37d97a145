#version 450 core
// Lays the soft halos over the canvas: where a halo was cast by a stroke nearer than the
// surface at this pixel, that surface fades towards the paper, so lines behind a silhouette
// break off before they reach it (Loviscach). MAX blending in the halo buffer merged the halos
// of neighbouring edges, so zig-zag silhouettes leave no seams.
#include "../lines/spine_test.glsl"

layout(binding = TEXTURE_UNIT_HALO) uniform sampler2D u_halo;
uniform vec3 u_paper;
layout(location = 0) out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 h = texelFetch(u_halo, p, 0).rg;
    if (h.r <= 0.0) discard;
    // Only what lies behind the stroke (smaller inverse depth) is covered.
    if (stored_inv_depth(p) >= h.g * (1.0 - 1e-3)) discard;
    o_color = vec4(u_paper, clamp(h.r, 0.0, 1.0));
}
