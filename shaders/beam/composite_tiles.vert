#version 450 core
// The sparse composite's geometry: one instance per screen tile, a quad over the lit ones
// (u_tiles, from tiles.comp) and a degenerate one, culled before rasterisation, over the rest.
#include "screen_tiles.glsl"

layout(binding = TEXTURE_UNIT_TILES) uniform usampler2D u_tiles;
uniform ivec2 u_screen;

const ivec2 kCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));

void main() {
    int across = textureSize(u_tiles, 0).x;
    ivec2 tile = ivec2(gl_InstanceID % across, gl_InstanceID / across);
    if (texelFetch(u_tiles, tile, 0).r == 0u) {
        gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);  // all six corners here: no area, outside
        return;
    }
    vec2 corner = vec2(min((tile + kCorners[gl_VertexID]) * kTileSize, u_screen));
    gl_Position = vec4(corner / vec2(u_screen) * 2.0 - 1.0, 0.0, 1.0);
}
