#version 450 core
// The list of screen tiles the sparse composite shades (pass_tiles.cpp), as runs along each
// row (lit_tiles.glsl): a tile is lit when a pass marked it this frame (lit_tiles.glsl: beam
// blocks, bloom footprints, HUD fragments) or, with the phosphor, when the picture held light
// there last frame (it must be decayed in place; every other tile of the picture is exactly
// black). One invocation per row walks it and appends each run of lit tiles, in pieces of
// kMaxTileRun (all invocations take the same steps: a row's width). The first four words of
// the buffer are the indirect draw's command (6 vertices, one instance per listed run), its
// instance count reset to 0 before the dispatch. Reads only the marks, a few thousand bytes:
// no texel of any image.
#include "lit_tiles.glsl"

layout(local_size_x = 64) in;
layout(binding = TEXTURE_UNIT_MARKS) uniform usampler2D u_marks;        // this frame's marks
layout(binding = TEXTURE_UNIT_PICTURE_LIT) uniform usampler2D u_picture_lit;  // last frame's picture marks (only with u_phosphor)
uniform bool u_phosphor;
layout(std430, binding = TILE_LIST_BINDING) buffer TileList {
    uint vertex_count;
    uint instance_count;
    uint first_vertex;
    uint base_instance;
    uint tiles[];  // runs, encode_tile_run
};
// The tiles listed, for the next frame's choice of the bloom's first downsample (zeroed before).
layout(std430, binding = LIT_TILE_COUNT_BINDING) buffer LitTileCount { uint lit_tile_count; };

bool lit(ivec2 tile) {
    return texelFetch(u_marks, tile, 0).r != 0u ||
           (u_phosphor && texelFetch(u_picture_lit, tile, 0).r != 0u);
}

void main() {
    ivec2 size = textureSize(u_marks, 0);
    int y = int(gl_GlobalInvocationID.x);
    if (y >= size.y) return;
    int start = -1;  // the first tile of the open run, -1: none
    uint listed = 0u;
    for (int x = 0; x <= size.x; ++x) {
        bool on = x < size.x && lit(ivec2(x, y));
        if (on && start < 0) start = x;
        if (start >= 0 && (!on || x - start == kMaxTileRun)) {
            uint slot = atomicAdd(instance_count, 1u);
            tiles[slot] = encode_tile_run(ivec2(start, y), x - start);
            listed += uint(x - start);
            start = on ? x : -1;
        }
    }
    if (listed > 0u) atomicAdd(lit_tile_count, listed);
}
