#version 450 core
// LineMethod::compute: draws one quad (two triangles) per record of the edge buffer that
// shaders/lines/edges.comp filled, with no geometry shader, computed with the same code as
// lines.geom (edge_geometry.glsl). Its fragments (edge_quad.frag) look visibility up from the
// spine samples (spine_visibility.comp) instead of running the spine test.
// Drawn indexed (EDGE_CORNERS vertices per record, EdgeStorage::quad_indices), so each
// corner runs once, or unindexed (EDGE_VERTICES per record) straight from the append count.
#include "edge_record.glsl"
#include "../beam/beam_width.glsl"
#include "spine_samples.glsl"

layout(std430, binding = EDGE_RECORDS_BINDING) readonly buffer Records { EdgeRecord records[]; };
#include "../instance_data.glsl"
layout(std430, binding = SPINE_SPANS_BINDING) readonly buffer Spans { uvec4 spans[]; };
layout(std430, binding = EDGE_COMMAND_BINDING) readonly buffer Command { EDGE_COMMAND_MEMBERS; };

uniform uint u_capacity;  // records the buffer holds (the draw count may run past it)
uniform bool u_indexed;   // drawn through the quad indices: gl_VertexID counts corners
uniform uint u_sample_capacity;  // spine samples the sample buffer holds
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;

#ifdef MASK_MODE
flat out vec4 g_ends;     // spine end points (edge_quad.frag documents these)
#else
noperspective out vec4 g_line;
#endif
flat out vec4 g_shade;
flat out vec4 g_stretch;
flat out uvec4 g_samples;

#include "edge_geometry.glsl"
#include "../beam/beam_tiles.glsl"

// Two triangles of the strip-ordered corners 0 1 2 3.
const int kCorner[6] = int[6](0, 1, 2, 2, 1, 3);

void main() {
    uint id = uint(gl_VertexID);
    uint index = u_indexed ? id / EDGE_CORNERS : id / EDGE_VERTICES;
    int corner_k = u_indexed ? int(id % EDGE_CORNERS) : kCorner[id % EDGE_VERTICES];
    if (index >= u_capacity) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: drawn by nobody
        return;
    }
    EdgeRecord r = records[index];
    vec2 s0 = r.screen.xy, s1 = r.screen.zw;
    vec2 dir, nrm;
    spine_frame(s0, s1, dir, nrm);
#ifdef MASK_MODE
    g_ends = vec4(s0, s1);
#endif
    uint instance = r.ids.y;
    // The beam's shape per edge; the flicker key is the edge's own id in its mesh and instance.
    BeamShape beam = beam_shape(instance_params(instance).z, length(s1 - s0),
                                (instance * 0x01000193u) ^ r.ids.z);
    g_shade = vec4(instance_color(instance).rgb * beam.gain, beam.half_width);
    g_stretch = vec4(-1.0, 2.0, beam.softness, 0.0);
    // When the frame asked for more samples than fit, every record is tested per fragment
    // (spine_visibility.comp skipped them all), so that which records got samples - the order
    // of the atomic appends - never shows.
    g_samples = uvec4(r.vertices.z, samples_used <= u_sample_capacity ? r.vertices.w : 0u, 0u, index);
    // With spine samples the quad covers only the visible stretch: from half a sample before
    // the first visible sample to half a sample after the last, where the look-up would turn
    // hidden. A wholly hidden edge draws nothing; a stretch without hidden samples inside
    // needs no look-ups, only the stretch's ends (edge_quad.frag).
    vec2 q0 = s0, q1 = s1;
    if (g_samples.y > 0u) {
        uvec4 span = spans[2u * index];
        uint visible_n = spans[2u * index + 1u].x;
        g_samples.z = span.x;
        if (span.z > span.w) {
            gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
            return;
        }
        // Look-ups only with hidden samples inside the stretch; then w holds how many samples
        // are stored, so a look-up never leaves them.
        g_stretch.w = visible_n < span.w - span.z + 1u ? float(span.y - span.x + 1u) : 0.0;
        if (g_samples.y > 1u) {
            float steps = float(g_samples.y - 1u);
            g_stretch.xy = vec2((float(span.z) - 0.5) / steps, (float(span.w) + 0.5) / steps);
            q0 = mix(s0, s1, max(g_stretch.x, 0.0));
            q1 = mix(s0, s1, min(g_stretch.y, 1.0));
        }
    }
    // Past a true end the quad reaches over the lengthened beam (beam_ends.glsl); past a
    // visible stretch's inner end the fragments are hidden anyway.
    // The quad's vertices share the marks of its tiles: the visible stretch, lengthened at
    // true ends.
    uint parts = u_indexed ? EDGE_CORNERS : EDGE_VERTICES;
    mark_beam_segment_part(q0, q1, beam.half_width, beam_end_reach(beam.half_width),
                           int(id % parts), int(parts));
    vec2 corner = quad_corner(q0, q1, dir, nrm, beam.half_width, beam_end_reach(beam.half_width),
                              corner_k);
#ifndef MASK_MODE
    // The corner in the spine's own frame. All four are affine in the window position, so
    // the rasteriser interpolates them exactly (noperspective) and the fragment needs no
    // projection onto the spine: t along it, the distance across, and the distance along it
    // from each end.
    float len = length(s1 - s0);
    vec2 rel = corner - s0;
    float along = dot(rel, dir);
    g_line = vec4(len > 1e-6 ? along / len : 0.0, dot(rel, nrm), along, along - len);
#endif
    gl_Position = vec4(corner / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
