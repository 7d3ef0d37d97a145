#version 450 core
// The sparse composite's geometry: one quad per listed tile (tile_list.comp), drawn with the
// list's indirect command, so the vertex work grows with the lit tiles, not the screen.
#include "lit_tiles.glsl"

layout(std430, binding = TILE_LIST_BINDING) readonly buffer TileList {
    uint vertex_count;
    uint instance_count;
    uint first_vertex;
    uint base_instance;
    uint tiles[];  // x | y << 16
};
uniform ivec2 u_screen;

const ivec2 kCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));

void main() {
    uint code = tiles[gl_InstanceID];
    ivec2 tile = ivec2(int(code & 0xffffu), int(code >> 16));
    vec2 corner = vec2(min((tile + kCorners[gl_VertexID]) * kLitTile, u_screen));
    gl_Position = vec4(corner / vec2(u_screen) * 2.0 - 1.0, 0.0, 1.0);
}
