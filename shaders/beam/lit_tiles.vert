#version 450 core
// The sparse composite's geometry: one quad per listed run of lit tiles (tile_list.comp),
// drawn with the list's indirect command, so the vertex work grows with the lit runs, not the
// screen.
#include "lit_tiles.glsl"

layout(std430, binding = TILE_LIST_BINDING) readonly buffer TileList {
    uint vertex_count;
    uint instance_count;
    uint first_vertex;
    uint base_instance;
    uint tiles[];  // runs, encode_tile_run
};
uniform ivec2 u_screen;

const ivec2 kCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));

void main() {
    ivec3 run = decode_tile_run(tiles[gl_InstanceID]);
    ivec2 corner_tile = run.xy + kCorners[gl_VertexID] * ivec2(run.z, 1);
    vec2 corner = vec2(min(corner_tile * kLitTile, u_screen));
    gl_Position = vec4(corner / vec2(u_screen) * 2.0 - 1.0, 0.0, 1.0);
}
