#version 450 core
// The depth tiles of hierarchical-Z culling (src/render/lines/hiz_culling.h): one invocation
// per tile keeps the inverse view depth of the farthest surface under it. u_level 0 reduces
// the prepass depth over DEPTH_TILE_SIZE-pixel squares into the fine tiles; u_level 1 reduces
// COARSE_DEPTH_TILES-tile squares of the fine tiles into the coarse ones. Inverse depth as the
// spine test reads it (spine_test.glsl: stored_inv_depth), so a cleared texel gives 1/far.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = TEXTURE_UNIT_DEPTH) uniform sampler2D u_depth;
layout(binding = TEXTURE_UNIT_DEPTH_TILES) uniform sampler2D u_fine;
layout(r32f, binding = IMAGE_UNIT_DEPTH_TILES) uniform writeonly image2D u_out;
uniform int u_level;
uniform ivec2 u_out_size;
uniform float u_proj_a;  // stored depth -> inverse view depth: (ndc + a) * inv_b
uniform float u_proj_inv_b;
uniform bool u_depth_zero_to_one;

void main() {
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(tile, u_out_size))) return;
    float farthest = 1.0 / 0.0;
    if (u_level == 0) {
        ivec2 size = textureSize(u_depth, 0);
        ivec2 lo = tile * DEPTH_TILE_SIZE, hi = min(lo + DEPTH_TILE_SIZE, size);
        // The smallest stored inverse depth is the largest or smallest stored depth, by the
        // sign of inv_b (reversed-Z stores 1 at the near plane): reduce the stored values, then
        // convert once.
        float lo_d = 1.0 / 0.0, hi_d = -1.0 / 0.0;
        for (int y = lo.y; y < hi.y; ++y) {
            for (int x = lo.x; x < hi.x; ++x) {
                float d = texelFetch(u_depth, ivec2(x, y), 0).r;
                lo_d = min(lo_d, d);
                hi_d = max(hi_d, d);
            }
        }
        float ndc_lo = u_depth_zero_to_one ? lo_d : 2.0 * lo_d - 1.0;
        float ndc_hi = u_depth_zero_to_one ? hi_d : 2.0 * hi_d - 1.0;
        farthest = min((ndc_lo + u_proj_a) * u_proj_inv_b, (ndc_hi + u_proj_a) * u_proj_inv_b);
    } else {
        ivec2 size = textureSize(u_fine, 0);
        ivec2 lo = tile * COARSE_DEPTH_TILES, hi = min(lo + COARSE_DEPTH_TILES, size);
        for (int y = lo.y; y < hi.y; ++y)
            for (int x = lo.x; x < hi.x; ++x) farthest = min(farthest, texelFetch(u_fine, ivec2(x, y), 0).r);
    }
    imageStore(u_out, tile, vec4(farthest));
}
