#version 450 core
// Marks the screen tiles the composite must shade (pass_tiles.cpp): a tile is lit when any
// texel of the picture under it is non-zero (u_occupancy, the bloom's first downsample's
// second output: exact, it averages every picture texel of its block) or when the bilinear
// footprint of its pixels in the finished bloom holds a non-zero texel. Everything else
// composites to exact black, which the clear writes for free.
// With the phosphor, a tile is also shaded where the picture held light last frame (it must
// be decayed, in place): the composite marks those as it stores them, and every other tile
// of the picture is exactly black, which an unshaded tile leaves as it is.
#include "screen_tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D u_occupancy;  // bloom resolution: > 0 where the block holds light
uniform sampler2D u_bloom;      // the finished bloom, encoded (bloom_encoding.glsl)
uniform ivec2 u_screen;         // target size in pixels
uniform bool u_phosphor;
uniform usampler2D u_picture_lit;  // per tile: the picture held light last frame
layout(r8ui, binding = 0) uniform writeonly uimage2D u_tiles;

// Texels of a `size`-texel image stretched over the screen that pixels [lo, hi] read:
// exactly the ones their block covers (nearest), or with `filtered` every texel a bilinear
// fetch at their centres touches, plus one of margin against rounding.
ivec4 texel_span(ivec2 lo, ivec2 hi, ivec2 size, bool filtered) {
    vec2 scale = vec2(size) / vec2(u_screen);
    if (!filtered) return ivec4(lo * size / u_screen, min(hi * size / u_screen, size - 1));
    ivec2 a = ivec2(floor((vec2(lo) + 0.5) * scale - 0.5)) - 1;
    ivec2 b = ivec2(floor((vec2(hi) + 0.5) * scale - 0.5)) + 2;
    return ivec4(clamp(a, ivec2(0), size - 1), clamp(b, ivec2(0), size - 1));
}

bool any_lit(sampler2D image, ivec4 span) {
    for (int y = span.y; y <= span.w; ++y) {
        for (int x = span.x; x <= span.z; ++x) {
            if (any(greaterThan(texelFetch(image, ivec2(x, y), 0).rgb, vec3(0.0)))) return true;
        }
    }
    return false;
}

void main() {
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(tile, imageSize(u_tiles)))) return;
    ivec2 lo = tile * kTileSize;
    ivec2 hi = min(lo + kTileSize, u_screen) - 1;
    bool lit = (u_phosphor && texelFetch(u_picture_lit, tile, 0).r != 0u) ||
               any_lit(u_occupancy, texel_span(lo, hi, textureSize(u_occupancy, 0), false)) ||
               any_lit(u_bloom, texel_span(lo, hi, textureSize(u_bloom, 0), true));
    imageStore(u_tiles, tile, uvec4(lit ? 1u : 0u));
}
