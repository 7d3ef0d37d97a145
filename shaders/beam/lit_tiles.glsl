// The lit-tile marks (Targets::lit_tiles, R8UI, one texel per LIT_TILE_SIZE square of the
// screen): the passes that already know where light is mark the tiles the composite must
// shade, and tile_list.comp turns the marks into a list for one indirect draw. Every store
// writes the same 1, so the order of the stores does not matter.
//  - the bloom's first downsample: the tile under each lit block of the beam image (a block
//    lies in one tile: the bloom's divisor divides LIT_TILE_SIZE);
//  - the bloom's last step: every tile a bilinear fetch of a non-zero texel can reach;
//  - the composite, with the phosphor: the tile of each lit pixel of the new picture (into
//    Targets::picture_lit, which the next frame's list reads).
// LIT_TILE_SIZE (pixels) comes from render/targets.h.
const int kLitTile = LIT_TILE_SIZE;

// The list holds runs of lit tiles along a row (tile_list.comp), one quad each: on llvmpipe a
// quad costs its setup and binning whatever its size, and a glow's tiles come in runs.
// A run is packed in one word: first tile x (12 bits), y (12 bits), length - 1 (8 bits);
// Renderer::read_lit_tiles unpacks the same way. A GL texture is at most 16384 pixels across,
// 1024 tiles: x and y fit.
const int kMaxTileRun = 256;
uint encode_tile_run(ivec2 first, int length) {
    return uint(first.x) | (uint(first.y) << 12) | (uint(length - 1) << 24);
}
ivec3 decode_tile_run(uint code) {  // x, y, length
    return ivec3(int(code & 0xfffu), int((code >> 12) & 0xfffu), int(code >> 24) + 1);
}

#ifdef LIT_TILES
layout(r8ui, binding = IMAGE_UNIT_LIT_TILES) uniform writeonly uimage2D u_lit_tiles;
uniform bool u_mark_tiles;  // false: no mark image is bound (the every-pixel composite)

// Marks every tile that holds a pixel of [lo, hi] (inclusive, clipped to the screen).
void mark_pixels(ivec2 lo, ivec2 hi) {
    if (!u_mark_tiles) return;
    ivec2 last = imageSize(u_lit_tiles) - 1;
    ivec2 a = clamp(max(lo, ivec2(0)) / kLitTile, ivec2(0), last);
    ivec2 b = clamp(max(hi, ivec2(0)) / kLitTile, ivec2(0), last);
    for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) imageStore(u_lit_tiles, ivec2(x, y), uvec4(1u));
}

// The screen pixels that can read texel `texel` of an image `factor` times smaller than the
// screen through a bilinear fetch at their centres: pixel x samples at (x + 0.5) / factor -
// 0.5 and reads the texels at floor of that and the next, so texel i is read by
// (i - 0.5) factor - 0.5 <= x < (i + 1.5) factor - 0.5, plus one pixel on each side against
// the rounding of the fetch's coordinate: 10 pixels at a quarter-resolution bloom.
void mark_bloom_texel(ivec2 texel, int factor) {
    vec2 i = vec2(texel);
    ivec2 lo = ivec2(ceil((i - 0.5) * float(factor) - 0.5)) - 1;
    ivec2 hi = ivec2(ceil((i + 1.5) * float(factor) - 0.5));
    mark_pixels(lo, hi);
}

// Whether an encoded bloom texel is stored as light in 8 bits (rounded to the nearest step;
// a hair below half a step marks too, so that a tie never leaves a lit texel unmarked). A
// fainter value stores as 0 and composites as no glow at all.
bool stores_light(vec3 encoded) {
    return max(encoded.r, max(encoded.g, encoded.b)) * 255.0 >= 0.499;
}
#endif
