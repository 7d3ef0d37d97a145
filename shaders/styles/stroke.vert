#version 450 core
// The stroke styles' quads: one per record of the edge buffer (shaders/lines/edge_record.glsl),
// drawn with the count the edge-extraction compute shader appended (glDrawArraysIndirect), no
// geometry shader. The quad is sized for what the fragment stage draws in it:
//   STROKE_OUTLINE  toon / pop-art ink (Castro & Macedo): centred on the edge, or one-sided (pushed
//                   outward from a silhouette); extended by `overdraw` x edge length at both ends
//   STROKE_SKETCH   several jittered pencil strokes (Olejnik & Litchmore): widened by the jitter
//   STROKE_HALO     silhouette strokes reaching inside and outside, plus the soft halo, bent by
//                   the cubic smoothing (Loviscach); HALO_GLOW draws the same quad into the halo
//                   buffer
// Besides the spine test's varyings (as edge_quad.vert hands lines.frag) each quad carries the
// edge's stable id (per-edge noise seeds), its outward direction and the smoothing slopes.
#include "../lines/edge_record.glsl"

layout(std430, binding = EDGE_RECORDS_BINDING) readonly buffer Records { EdgeRecord records[]; };
#include "../instance_data.glsl"

uniform uint u_capacity;
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;
uniform float u_width_px;      // outline / stroke width
uniform float u_overdraw;      // outline: end extension, fraction of the edge's length
uniform bool u_one_sided;      // outline: silhouettes extruded outward only
uniform float u_jitter_px;     // sketch
uniform float u_inner_px;      // halo stroke inside the silhouette
uniform float u_outer_px;      // ... outside
uniform float u_halo_px;       // soft halo beyond the stroke
uniform bool u_smoothing;      // halo: cubic smoothing on

noperspective out vec2 g_pixel;
flat out vec2 g_p0;
flat out vec2 g_p1;
flat out vec2 g_inv_depth;
flat out vec3 g_edge_plane;
flat out vec3 g_face_pos;
flat out vec3 g_face_neg;
flat out vec2 g_nudge;
flat out vec3 g_color;
flat out uint g_kind;
flat out uint g_seed;          // stable per edge and mesh: the same strokes every frame
flat out vec2 g_outward;       // unit screen direction away from the front face (silhouettes)
flat out vec2 g_slopes;        // cubic smoothing: offset slopes at p0 and p1 (0 = straight)
flat out float g_significance; // sketch: how much the edge matters under the light

uniform vec3 u_light_dir;      // view space, towards the light

#include "../lines/edge_geometry.glsl"
#include "../beam/beam_tiles.glsl"

const int kCorner[6] = int[6](0, 1, 2, 2, 1, 3);

uint hash_u32(uint x) {
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// The slope (offset per unit of chord length, along nrm) of the tangent that runs
// perpendicular to the projected vertex normal at window point s with view point p.
float smoothing_slope(vec2 s, vec3 p, vec3 n, vec2 dir, vec2 nrm) {
    if (dot(n, n) < 0.5) return 0.0;
    vec3 q = p + n * (0.01 * max(-p.z, u_near));
    vec4 cq = u_proj * vec4(q, 1.0);
    if (cq.w <= 0.0) return 0.0;
    vec2 sn = to_window(cq) - s;
    if (dot(sn, sn) < 1e-10) return 0.0;
    vec2 t = vec2(-sn.y, sn.x);       // perpendicular to the projected normal
    if (dot(t, dir) < 0.0) t = -t;
    float along = dot(t, dir);
    if (along < 1e-3) return 0.0;
    return clamp(dot(t, nrm) / along, -1.0, 1.0);  // steeper would fold the curve
}

void main() {
    uint index = uint(gl_VertexID) / EDGE_VERTICES;
    if (index >= u_capacity) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    EdgeRecord r = records[index];
    vec2 s0 = r.screen.xy, s1 = r.screen.zw;
    vec2 dir, nrm;
    spine_frame(s0, s1, dir, nrm);
    float len = distance(s0, s1);
    uint kind = r.ids.x & EDGE_KIND_MASK;
    vec2 outward = kind == EDGE_SILHOUETTE ? normalize(silhouette_nudge(r.edge_plane.xyz, s0, nrm)) : vec2(0.0);

    g_p0 = s0;
    g_p1 = s1;
    g_inv_depth = r.depth.xy;
    g_edge_plane = r.edge_plane.xyz;
    g_face_pos = r.face_pos.xyz;
    g_face_neg = r.face_neg.xyz;
    g_nudge = kind == EDGE_SILHOUETTE ? outward * 0.75 : vec2(0.0);
    g_color = instance_color(r.ids.y).rgb;
    g_kind = kind;
    // The edge id is stable for a mesh; mixing in the mesh id keeps two models apart.
    g_seed = hash_u32(r.ids.z * 0x9e3779b9u ^ hash_u32(r.ids.w + 0x51u));
    g_outward = outward;
    g_slopes = vec2(0.0);
    g_significance = 1.0;

    // Quad extent: ext along the edge at both ends; lo / hi across it, along -nrm / +nrm.
    float ext = 1.0, lo = 1.0, hi = 1.0;
#if defined(STROKE_OUTLINE)
    ext = u_overdraw * len + u_width_px * 0.5 + 1.0;
    if (u_one_sided && kind == EDGE_SILHOUETTE) {
        bool up = dot(outward, nrm) > 0.0;
        lo = up ? 1.0 : u_width_px + 1.0;
        hi = up ? u_width_px + 1.0 : 1.0;
    } else {
        lo = hi = u_width_px * 0.5 + 1.0;
    }
#elif defined(STROKE_SKETCH)
    // Significance (Jezek et al.): a crease between faces the light reaches fully matters
    // little; silhouettes and boundaries always matter.
    vec3 l = normalize(u_light_dir);
    float lit_a = max(dot(r.normal_a.xyz, l), 0.0);
    float lit_b = dot(r.normal_b.xyz, r.normal_b.xyz) > 0.5 ? max(dot(r.normal_b.xyz, l), 0.0) : lit_a;
    g_significance = kind == EDGE_CREASE ? 1.0 - min(lit_a, lit_b) : 1.0;
    float j = min(u_jitter_px, 0.25 * len + 0.5);
    ext = j + u_width_px + 1.0;
    lo = hi = 1.5 * j + u_width_px + 1.0;
#else
    float bulge = 0.0;
    // Only where the mesh stands for a smooth surface: at a box's corner the vertex normal is
    // 55 degrees off every face, and bending its edges would round the box.
    vec3 va = r.vertex_normal_a.xyz, vb = r.vertex_normal_b.xyz, fa = r.normal_a.xyz, fb = r.normal_b.xyz;
    float agree = min(min(dot(va, fa), dot(vb, fa)), min(dot(va, fb), dot(vb, fb)));
    if (u_smoothing && kind == EDGE_SILHOUETTE && agree > 0.75) {
        vec3 pa = ray_at(s0) / max(r.depth.x, 1e-30);
        vec3 pb = ray_at(s1) / max(r.depth.y, 1e-30);
        g_slopes = vec2(smoothing_slope(s0, pa, r.vertex_normal_a.xyz, dir, nrm),
                        smoothing_slope(s1, pb, r.vertex_normal_b.xyz, dir, nrm));
        // |h10| and |h11| peak at 4/27 of the chord.
        bulge = (abs(g_slopes.x) + abs(g_slopes.y)) * len * (4.0 / 27.0);
    }
#ifdef HALO_GLOW
    // The glow lies outside the smoothed silhouette only (halo.frag), which bends inward by at
    // most the bulge; other edges cast none, so their quads are empty and mark no tile (the
    // halo's paper layer runs over the marked tiles, pass_halo.cpp).
    if (kind != EDGE_SILHOUETTE) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    float reach_out = u_outer_px + u_halo_px + bulge + 2.0;
    float reach_in = bulge + 2.0;
#else
    // The ink reaches u_outer_px + 1.2 px (its offsets) from the curve, measured across it:
    // along nrm that is up to sqrt(1 + slope^2) further, and the slope is at most
    // |slope0| + |slope1|. Reaching out as far as the halo cost the ink pass ~3x its area.
    float steepest = abs(g_slopes.x) + abs(g_slopes.y);
    float reach_out = (u_outer_px + 2.0) * sqrt(1.0 + steepest * steepest) + bulge;
    float reach_in = u_inner_px + bulge + 2.0;
#endif
    bool up = kind != EDGE_SILHOUETTE || dot(outward, nrm) > 0.0;
    lo = up ? reach_in : reach_out;
    hi = up ? reach_out : reach_in;
    ext = max(u_inner_px, u_outer_px) + 1.0;
#endif
#ifdef HALO_GLOW
    // The halo is laid over the tiles its quads may cover (pass_halo.cpp); the quad's six
    // vertices share the marks (beam_tiles.glsl). The quad spans -lo .. +hi across the edge,
    // mostly outward: the band around its middle, not max(lo, hi) to both sides (a fifth fewer
    // tiles along a long silhouette).
    vec2 middle = nrm * (0.5 * (hi - lo));
    mark_beam_segment_part(s0 + middle, s1 + middle, 0.5 * (lo + hi), ext,
                           int(uint(gl_VertexID) % EDGE_VERTICES), int(EDGE_VERTICES));
#endif
    int k = kCorner[uint(gl_VertexID) % EDGE_VERTICES];
    vec2 end = k < 2 ? s0 - dir * ext : s1 + dir * ext;
    g_pixel = end + ((k & 1) == 0 ? -nrm * lo : nrm * hi);
    // Depth of the spine at this end, so the halo's quads can be depth-tested in hardware
    // against the shrunk-mesh mask; 1/depth is affine along the screen spine.
    float inv = k < 2 ? r.depth.x : r.depth.y;
    float w = 1.0 / max(inv, 1e-30);
    vec4 clip = u_proj * vec4(0.0, 0.0, -w, 1.0);
    gl_Position = vec4((g_pixel / u_viewport * 2.0 - 1.0) * clip.w, clip.z, clip.w);
}
