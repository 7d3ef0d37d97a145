// Marks the screen tiles a beam quad may light (BEAM_TILES; the stages that build the quads of
// the scene's lines and the HUD): the bloom's first downsample then reads the beam image only
// under marked tiles (pass_bloom.cpp). Once per quad, not per fragment: on llvmpipe a store
// from every line fragment cost about as much as the pixels it saved the downsample.
// TILE_SIZE (pixels) comes from render/targets.h. Every store writes the same 1.
#ifdef BEAM_TILES
layout(r8ui, binding = IMAGE_UNIT_BEAM_TILES) uniform writeonly uimage2D u_beam_tiles;
// true: this frame's bloom reads the whole beam image (RenderSettings::first_downsample), so
// nothing is marked. Unset it is false: the stages that mark for other passes (the halo, the
// ink composite's HUD) keep marking.
uniform bool u_skip_beam_tiles;

// The quad of segment s0-s1 (pixels): lengthened by `reach` past both ends, `half_width` to
// each side. Points half a tile apart along it, each marking the tiles within half_width +
// half a tile + 1 px (a box that holds every pixel centre of the quad near that point), over
// the part of the segment that can reach the screen.
// Of those points this call marks every `parts`-th from `part` on: the vertices of one quad
// share its marks (part = the vertex's place in the quad), so that the SIMD lanes of a vertex
// shader loop together instead of one lane per quad looping while the other corners wait.
void mark_beam_segment_part(vec2 s0, vec2 s1, float half_width, float reach, int part, int parts) {
    if (u_skip_beam_tiles) return;
    ivec2 tiles = imageSize(u_beam_tiles);
    float step_px = 0.5 * float(TILE_SIZE);
    float margin = half_width + step_px + 1.0;
    vec2 d = s1 - s0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 a = s0 - dir * reach, v = (s1 + dir * reach) - a;
    vec2 lo = vec2(-margin), hi = vec2(tiles * TILE_SIZE) + margin;
    float t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {  // clip to the screen grown by the margin
        if (abs(v[axis]) < 1e-6) {
            if (a[axis] < lo[axis] || a[axis] > hi[axis]) return;
            continue;
        }
        float ta = (lo[axis] - a[axis]) / v[axis], tb = (hi[axis] - a[axis]) / v[axis];
        t0 = max(t0, min(ta, tb));
        t1 = min(t1, max(ta, tb));
    }
    if (t0 > t1) return;
    vec2 p = a + v * t0, q = a + v * t1;
    int n = int(ceil(length(q - p) / step_px));
    for (int i = part; i <= n; i += parts) {
        vec2 c = n > 0 ? mix(p, q, float(i) / float(n)) : p;
        ivec2 first = max(ivec2(floor((c - margin) / float(TILE_SIZE))), ivec2(0));
        ivec2 last = min(ivec2(floor((c + margin) / float(TILE_SIZE))), tiles - 1);
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) imageStore(u_beam_tiles, ivec2(x, y), uvec4(1u));
    }
}

void mark_beam_segment(vec2 s0, vec2 s1, float half_width, float reach) {
    mark_beam_segment_part(s0, s1, half_width, reach, 0, 1);
}
#else
void mark_beam_segment_part(vec2 s0, vec2 s1, float half_width, float reach, int part, int parts) {}
void mark_beam_segment(vec2 s0, vec2 s1, float half_width, float reach) {}
#endif
