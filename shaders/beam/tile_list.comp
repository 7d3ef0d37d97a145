#version 450 core
// The list of screen tiles the sparse composite shades (pass_tiles.cpp): one invocation per
// tile appends it when a pass marked it lit this frame (lit_tiles.glsl: beam blocks, bloom
// footprints) or, with the phosphor, when the picture held light there last frame (it must be
// decayed in place; every other tile of the picture is exactly black). The first four words
// of the buffer are the indirect draw's command (6 vertices, one instance per listed tile),
// its instance count reset to 0 before the dispatch. Reads only the marks, a few thousand
// bytes: no texel of any image.
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
    uint tiles[];  // x | y << 16
};

void main() {
    ivec2 size = textureSize(u_marks, 0);
    int i = int(gl_GlobalInvocationID.x);
    if (i >= size.x * size.y) return;
    ivec2 tile = ivec2(i % size.x, i / size.x);
    bool lit = texelFetch(u_marks, tile, 0).r != 0u ||
               (u_phosphor && texelFetch(u_picture_lit, tile, 0).r != 0u);
    if (!lit) return;
    uint slot = atomicAdd(instance_count, 1u);
    tiles[slot] = uint(tile.x) | (uint(tile.y) << 16);
}
