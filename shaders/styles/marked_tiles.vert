#version 450 core
// The filled styles' passes that shade only where something was drawn (pass_ink_composite.cpp:
// the HUD's ink and halo; pass_halo.cpp: the halo laid over the canvas). One instance per
// screen tile: a quad over every tile within u_reach tiles of a marked one (beam_tiles.glsl),
// a degenerate one, culled before rasterisation, over the rest.
layout(binding = TEXTURE_UNIT_TILES) uniform usampler2D u_tiles;
uniform ivec2 u_screen;
uniform int u_reach;  // tiles: how far past the marked ones a pass may change pixels
out vec2 v_uv;

const ivec2 kCorners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));

bool near_lit(ivec2 tile, ivec2 tiles) {
    for (int y = max(tile.y - u_reach, 0); y <= min(tile.y + u_reach, tiles.y - 1); ++y)
        for (int x = max(tile.x - u_reach, 0); x <= min(tile.x + u_reach, tiles.x - 1); ++x)
            if (texelFetch(u_tiles, ivec2(x, y), 0).r != 0u) return true;
    return false;
}

void main() {
    ivec2 tiles = textureSize(u_tiles, 0);
    ivec2 tile = ivec2(gl_InstanceID % tiles.x, gl_InstanceID / tiles.x);
    v_uv = vec2(0.0);
    if (!near_lit(tile, tiles)) {
        gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);  // all six corners here: no area, outside
        return;
    }
    vec2 corner = vec2(min((tile + kCorners[gl_VertexID]) * TILE_SIZE, u_screen));
    gl_Position = vec4(corner / vec2(u_screen) * 2.0 - 1.0, 0.0, 1.0);
}
