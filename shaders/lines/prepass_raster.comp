#version 450 core
// The depth prepass of small triangles, rasterised here instead of by the GL pipeline
// (render/lines/prepass_raster.h). On llvmpipe the pipeline transforms, clips and sets up
// every triangle on one thread, which a mesh of many tiny triangles pays per triangle; here
// every thread takes its share. One work group per work item: a cluster of one instance's
// triangles whose bounding sphere the CPU found small on screen and wholly beyond the near
// plane, so no triangle needs clipping and each covers few pixel centres. Each of the
// cluster's vertices is projected once (about 6 triangles share one), as the pipeline's
// vertex cache would.
//
// The same rules as the pipeline's: a pixel is covered when its centre lies inside the
// triangle or on its edge (edges shared by two triangles are evaluated the same way from both,
// so no centre falls between them), depth is z/w interpolated linearly across the window,
// pixels beyond the far plane are dropped, and for a work item with flag 1
// triangles wound clockwise on screen are skipped, as glCullFace(GL_BACK) does. Reversed-Z
// float depth only: nearer is greater, and non-negative floats order as their bits, so the
// nearest surface is an atomic maximum on the bits (0 = the clear: nothing).
#include "../instance_data.glsl"

// One invocation per vertex of a cluster (at most geo::kClusterVertices = 64), then per
// triangle.
layout(local_size_x = 64) in;

layout(std430, binding = EDGE_POSITIONS_BINDING) readonly buffer Positions { float positions[]; };
// Each cluster's distinct vertices, and per triangle its corners into its cluster's list
// (a | b << 8 | c << 16): geo::ClusteredTriangles::vertices and corners.
layout(std430, binding = RASTER_VERTICES_BINDING) readonly buffer Vertices { uint vertices[]; };
layout(std430, binding = RASTER_CORNERS_BINDING) readonly buffer Corners { uint corners[]; };
// render::RasterItem packed: x instance, y first triangle, z triangles | vertices << 8 |
// skip back faces << 16, w first vertex.
layout(std430, binding = RASTER_WORK_BINDING) readonly buffer Work { uvec4 work[]; };
layout(binding = IMAGE_UNIT_RASTER_DEPTH, r32ui) uniform coherent uimage2D u_depth;

uniform uint u_work_base;  // this mesh's first work item
uniform mat4 u_proj;
uniform ivec2 u_viewport;

vec3 window_point(uint v, mat4 model_view) {
    // As prepass.vert computes it: u_proj * (model_view * p).
    vec4 p = vec4(positions[3u * v], positions[3u * v + 1u], positions[3u * v + 2u], 1.0);
    vec4 c = u_proj * (model_view * p);
    vec3 n = c.xyz / c.w;
    return vec3((n.xy * 0.5 + 0.5) * vec2(u_viewport), n.z);
}

// An edge a -> b as the pixel loop evaluates it: e(q) = sign * ((q - o) x d), twice the signed
// area of (a, b, q), positive when q lies left of a -> b. Set up with the endpoints in one fixed
// order and the sign flipped, so the triangles on both sides of an edge get exactly opposite
// values at every pixel centre: none falls through the gap between them.
struct Edge {
    vec2 o, d;
    float sign;
};

Edge edge(vec2 a, vec2 b) {
    bool swap = a.x > b.x || (a.x == b.x && a.y > b.y);
    vec2 p0 = swap ? b : a, p1 = swap ? a : b;
    return Edge(p0, p1 - p0, swap ? -1.0 : 1.0);
}

float edge_function(Edge e, vec2 q) {
    return e.sign * (e.d.x * (q.y - e.o.y) - e.d.y * (q.x - e.o.x));
}

// The cluster's vertices in window space, each projected once by one invocation.
shared vec3 s_points[64];

void main() {
    uvec4 item = work[u_work_base + gl_WorkGroupID.x];
    uint triangles = item.z & 0xFFu, vertex_count = (item.z >> 8) & 0xFFu;
    bool skip_back = ((item.z >> 16) & 1u) != 0u;
    uint v = gl_LocalInvocationID.x;
    if (v < vertex_count) s_points[v] = window_point(vertices[item.w + v], instance_model_view(item.x));
    barrier();
    for (uint k = gl_LocalInvocationID.x; k < triangles; k += gl_WorkGroupSize.x) {
        uint c = corners[item.y + k];
        vec3 p0 = s_points[c & 0xFFu];
        vec3 p1 = s_points[(c >> 8) & 0xFFu];
        vec3 p2 = s_points[(c >> 16) & 0xFFu];
        float area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
        if (!(area != 0.0) || (skip_back && area < 0.0)) continue;
        if (area < 0.0) {  // a back face drawn: walk it the other way round
            vec3 s = p1;
            p1 = p2;
            p2 = s;
            area = -area;
        }
        Edge e0 = edge(p1.xy, p2.xy), e1 = edge(p2.xy, p0.xy), e2 = edge(p0.xy, p1.xy);
        ivec2 lo = max(ivec2(ceil(min(p0.xy, min(p1.xy, p2.xy)) - 0.5)), ivec2(0));
        ivec2 hi = min(ivec2(floor(max(p0.xy, max(p1.xy, p2.xy)) - 0.5)), u_viewport - 1);
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x) {
                vec2 q = vec2(x, y) + 0.5;
                float w0 = edge_function(e0, q);
                float w1 = edge_function(e1, q);
                float w2 = edge_function(e2, q);
                if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
                float z = (w0 * p0.z + w1 * p1.z + w2 * p2.z) / (w0 + w1 + w2);
                if (!(z >= 0.0)) continue;  // beyond the far plane (reversed-Z: 0)
                imageAtomicMax(u_depth, ivec2(x, y), floatBitsToUint(z));
            }
        }
    }
}
