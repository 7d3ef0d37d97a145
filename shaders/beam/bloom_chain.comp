#version 450 core
// The bloom's mip chain from level u_first on, in one dispatch of one workgroup
// (BloomChain::compute; pass_bloom.cpp): down, level k = the 2x2 box of level k-1 (one bilinear
// fetch at the centre of each block, as bloom_down.frag; level u_first - 1 is a texture); then
// up, level k += u_ratio[k] * the bilinear upsample of level k+1 (bloom_up.frag's S_k), back to
// level u_first, which it writes to its texture for the steps after it. The walked levels live
// in a buffer as 32-bit floats.
// Why one workgroup: on llvmpipe each draw or dispatch of the chain cost 0.07-0.15 ms of setup
// and thread hand-over, far more than the small levels' texels; one workgroup steps from level
// to level with barrier() (docs/measurements/bloom-chain.md). The levels it walks are small
// ones (pass_bloom.cpp's first_walked_level): it runs on one thread. On a GPU it would keep one
// of many cores busy; there the pipeline draws every level (BloomChain::automatic).
// The workgroup steps over each level in 16x16 blocks: no division to find a lane's texel
// (x86 has no vector integer division; llvmpipe would run it lane by lane).
layout(local_size_x = 16, local_size_y = 16) in;
const int kBlock = 16;
layout(binding = TEXTURE_UNIT_SOURCE) uniform sampler2D u_finer;  // level u_first - 1
layout(rgba16f, binding = IMAGE_UNIT_BLOOM_LEVEL) uniform writeonly image2D u_first_level;
layout(std430, binding = BLOOM_CHAIN_BINDING) coherent buffer ChainTexels { vec4 texels[]; };
// Uniform arrays rather than sizes derived here: llvmpipe keeps a private array per lane in
// memory, and the fetches below index it four times per bilinear sample.
uniform int u_first;                       // the first level walked (>= 1)
uniform int u_levels;                      // n, level 0 included (2 .. MAX_BLOOM_LEVELS)
uniform ivec2 u_size[MAX_BLOOM_LEVELS];    // each level's size in texels
uniform int u_offset[MAX_BLOOM_LEVELS];    // level k's first texel in the buffer (k >= u_first)
uniform float u_ratio[MAX_BLOOM_LEVELS];   // w_{k+1} / w_k

vec3 texel(int k, ivec2 t) {
    t = clamp(t, ivec2(0), u_size[k] - 1);  // clamp to edge, as the textures sample
    return texels[u_offset[k] + t.y * u_size[k].x + t.x].rgb;
}

// Level k sampled bilinearly at uv, as a linear-filtered texture is.
vec3 bilinear(int k, vec2 uv) {
    vec2 p = uv * vec2(u_size[k]) - 0.5;
    vec2 corner = floor(p);
    vec2 f = p - corner;
    ivec2 a = ivec2(corner);
    vec3 top = mix(texel(k, a), texel(k, a + ivec2(1, 0)), f.x);
    vec3 bottom = mix(texel(k, a + ivec2(0, 1)), texel(k, a + ivec2(1, 1)), f.x);
    return mix(top, bottom, f.y);
}

// Every lane's writes of this level are visible before any lane reads them for the next.
void level_done() {
    memoryBarrierBuffer();
    barrier();
}

void main() {
    const ivec2 lane = ivec2(gl_LocalInvocationID.xy);
    const int last = u_levels - 1;
    for (int k = u_first; k <= last; ++k) {
        const ivec2 size = u_size[k];
        for (int y = lane.y; y < size.y; y += kBlock)
        for (int x = lane.x; x < size.x; x += kBlock) {
            const ivec2 t = ivec2(x, y);
            const vec2 uv = (vec2(t) + 0.5) / vec2(size);
            const vec3 box =
                k == u_first ? textureLod(u_finer, uv, 0.0).rgb : bilinear(k - 1, uv);
            texels[u_offset[k] + y * size.x + x] = vec4(box, 1.0);
            if (k == u_first && k == last) imageStore(u_first_level, t, vec4(box, 1.0));
        }
        level_done();
    }
    for (int k = last - 1; k >= u_first; --k) {
        const ivec2 size = u_size[k];
        for (int y = lane.y; y < size.y; y += kBlock)
        for (int x = lane.x; x < size.x; x += kBlock) {
            const ivec2 t = ivec2(x, y);
            const vec2 uv = (vec2(t) + 0.5) / vec2(size);
            const int i = u_offset[k] + y * size.x + x;
            const vec3 sum = texels[i].rgb + bilinear(k + 1, uv) * u_ratio[k];
            if (k == u_first) {
                imageStore(u_first_level, t, vec4(sum, 1.0));
            } else {
                texels[i] = vec4(sum, 1.0);
            }
        }
        level_done();
    }
}
