#version 450 core
// The spine test once per spine sample (spine_samples.glsl) instead of once per line
// fragment: one work group per edge record, its invocations spread along the spine. Writes
// each sample's answer, narrows the record's span of visible samples (first, last) and counts
// them, so a span without hidden samples inside needs no look-ups at all, so the quad pass can
// skip a hidden edge and draw a partly hidden one only over its visible stretch.
#include "edge_record.glsl"
#include "spine_samples.glsl"

// Eight invocations per record: one SIMD vector on llvmpipe, so a short edge (most of a dense
// mesh's) wastes few lanes; a long one loops (pass_spine_visibility.cpp has the measurements).
layout(local_size_x = 8) in;

layout(std430, binding = EDGE_RECORDS_BINDING) readonly buffer Records { EdgeRecord records[]; };
layout(std430, binding = EDGE_COMMAND_BINDING) buffer Command { EDGE_COMMAND_MEMBERS; };
layout(std430, binding = SPINE_SAMPLES_BINDING) writeonly buffer Samples { uint spine_samples[]; };
layout(std430, binding = SPINE_SPANS_BINDING) buffer Spans { uvec4 spans[]; };  // from edges.comp

uniform uint u_capacity;
uniform uint u_sample_capacity;
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;

#include "edge_geometry.glsl"
#include "spine_test.glsl"
#include "record_spine_test.glsl"

void main() {
    // The quad pass's two draws (pass_edge_quads.cpp): the records' quads with their samples,
    // or, when the frame asked for more samples than the buffer holds, every record's quad
    // tested per fragment (edge_quad.vert). Both index the quads' corners, which end at the
    // buffer's capacity: a frame that appended more records draws those that fit.
    bool overflow = samples_used > u_sample_capacity;
    if (gl_WorkGroupID.x == 0u && gl_LocalInvocationID.x == 0u) {
        uint indices = min(vertex_count, u_capacity * EDGE_VERTICES);
        sampled_draw_count = overflow ? 0u : indices;
        sampled_draw_instances = 1u;
        tested_draw_count = overflow ? indices : 0u;
        tested_draw_instances = 1u;
    }
    // Too many samples for the buffer: the quads test every record per fragment instead.
    if (overflow) return;
    uint records_n = min(vertex_count / EDGE_VERTICES, u_capacity);
    uint lane = gl_LocalInvocationID.x;
    for (uint index = gl_WorkGroupID.x; index < records_n; index += gl_NumWorkGroups.x) {
        EdgeRecord r = records[index];
        uint first_sample = r.vertices.z, count = r.vertices.w;
        if (count == 0u) continue;  // no room for its samples: the fragments test it
        uvec2 sampled = spans[2u * index].xy;  // the stretch on screen; its first sample is stored first
        vec2 nudge = record_nudge(r);
        uint first = 0xFFFFFFFFu, last = 0u, visible_n = 0u;
        for (uint k = sampled.x + lane; k <= sampled.y; k += gl_WorkGroupSize.x) {
            bool visible = record_spine_visible(r, spine_sample_t(k, count), nudge);
            spine_samples[first_sample + (k - sampled.x)] = visible ? 1u : 0u;
            if (visible) {
                ++visible_n;
                first = min(first, k);
                last = max(last, k);
            }
        }
        // Global atomics, not shared memory and barriers: llvmpipe runs a work group with a
        // barrier as coroutines, several times slower.
        if (first != 0xFFFFFFFFu) {
            atomicMin(spans[2u * index].z, first);
            atomicMax(spans[2u * index].w, last);
            atomicAdd(spans[2u * index + 1u].x, visible_n);
        }
    }
}
