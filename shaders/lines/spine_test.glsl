// The spine test (Cole & Finkelstein): a line fragment is visible when the point of the spine
// nearest to it is not behind the prepass depth. Every fragment across the line's width asks
// about the same spine point, so a line ends cleanly where it goes behind something.
//
// The depth a sample pixel should hold if the edge is unoccluded is not the spine's depth but
// the depth of the edge's own face at the pixel centre, which differs by the face's slope
// (large at grazing angles). So each edge carries the planes of its faces: the pixel's side of
// the eye-edge plane picks the face, and that plane's depth along the pixel's ray is exact.
// Because it is exact, the tolerance only has to cover how far the prepass may sit from the
// plane, and it is scale-aware instead of one relative constant:
//  - float rounding of vertices, planes and interpolation: relative to the depth (1e-5);
//  - the depth buffer's step (24-bit fixed point): a constant in inverse depth;
//  - rasterisation (sub-pixel vertex snapping): the plane's own depth slope per pixel times a
//    fraction of a pixel, so a grazing face gets the room it needs and a face-on one none,
//    capped at the relative depth_bias so a steep face cannot see through a thin surface.
// Where no face lies on the sample's side (a silhouette is sampled 0.75 px outside its front
// face, where an occluder or the background is) the texel's depth is carried back to the
// spine point along the stored surface's own slope and compared with the spine's depth. So a
// surface in front of the edge by more than the tolerance hides it however thin it is (a roof
// over rafters that touch its underside, a wall over studs), and a surface sloping away just
// behind a silhouette does not.
//
// Everything is compared as inverse view depth (1/v), which is affine in the stored depth and
// in a plane's equation, so the test needs no division: for a plane n.X = 1 (n pre-divided by
// n.p in the geometry shader) and the ray r = (x, y, -1) through a pixel, 1/v = n.r.
layout(binding = TEXTURE_UNIT_DEPTH) uniform sampler2D u_depth;
uniform bool u_occlusion;     // false in the arcade style: the 1980 machine hid nothing
uniform float u_proj_a;       // stored depth -> inverse view depth: (ndc + a) * inv_b
uniform float u_proj_inv_b;
uniform bool u_depth_zero_to_one;
uniform float u_tol_rel;        // relative inverse-depth tolerance (float rounding)
uniform float u_tol_abs;        // absolute inverse-depth tolerance (depth buffer step)
uniform float u_tol_px;         // rasterisation: pixels of the face's own depth slope
uniform float u_fallback_rel;   // relative tolerance where no face plane is usable, and the
                                // most the slope allowance may add
uniform vec4 u_ray;           // pixel -> view ray: xy = pixel * u_ray.xy + u_ray.zw, z = -1
uniform ivec2 u_depth_max;    // depth texture size - 1

float stored_inv_depth(ivec2 texel) {
    float d = texelFetch(u_depth, clamp(texel, ivec2(0), u_depth_max), 0).r;
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    return (ndc + u_proj_a) * u_proj_inv_b;  // cleared depth gives 1/far: nothing in front
}

// What the fragment stage knows of an edge's faces (all flat per edge).
struct EdgeFaces {
    vec3 edge_plane;  // through the eye and the edge; the positive side holds face_pos
    vec3 face_pos;    // face planes as n / (n.p): 1/depth along a ray r is dot(plane, r);
    vec3 face_neg;    // all zero: no face on that side
};

// Stored depths as inverse view depth, four at a time.
vec4 inv_depth4(vec4 d) {
    vec4 ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    return (ndc + u_proj_a) * u_proj_inv_b;
}

// The stored inverse depth at texel `t` and at its four neighbours (x: t + (1, 0), y:
// t - (1, 0), z: t + (0, 1), w: t - (0, 1)), clamped to the texture as stored_inv_depth
// clamps. Two gathers of 2x2 texels (at the corners t and t + 1, which lie half a texel from
// every centre, so rounding cannot pick other texels) instead of five fetches: on llvmpipe
// each fetch costs its own addressing and clamping for every sample.
float stored_inv_depth_cross(ivec2 t, out vec4 around) {
    vec2 inv_size = 1.0 / vec2(u_depth_max + 1);
    // textureGather's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0) around the corner.
    vec4 low = inv_depth4(textureGather(u_depth, vec2(t) * inv_size));
    vec4 high = inv_depth4(textureGather(u_depth, vec2(t + 1) * inv_size));
    around = vec4(high.z, low.x, high.x, low.z);
    return low.y;
}

// The stored surface's inverse depth at `p`, extrapolated from texel `t` (inverse depth `s`,
// its neighbours `around` as stored_inv_depth_cross gives them) along its own slope. Each
// axis takes the smaller of the forward and backward differences, so a texel next to a depth
// discontinuity uses the side that stays on its surface.
float stored_inv_depth_at(ivec2 t, vec2 p, float s, vec4 around) {
    float xp = around.x - s, xm = s - around.y;
    float yp = around.z - s, ym = s - around.w;
    vec2 g = vec2(abs(xp) < abs(xm) ? xp : xm, abs(yp) < abs(ym) ? yp : ym);
    return s + dot(g, p - (vec2(t) + 0.5));
}

// Is the texel `t` not covered by anything in front of the edge's own surface there?
// `spine_px` is the spine point the sample stands for.
bool sample_visible(ivec2 t, vec2 spine_px, float line_inv, EdgeFaces e) {
    vec3 r = vec3((vec2(t) + 0.5) * u_ray.xy + u_ray.zw, -1.0);
    vec3 f = dot(e.edge_plane, r) >= 0.0 ? e.face_pos : e.face_neg;
    float want = dot(f, r);
    vec4 around;
    float stored = stored_inv_depth_cross(t, around);
    // No face on that side (a silhouette's outside, a boundary), or a plane seen so edge-on
    // that its depth could be anywhere: compared with the spine's own depth below.
    if (want > line_inv * 0.25) {
        // d(1/v)/d(pixel) of the plane. The rasterisation allowance grows with the slope,
        // but never past the relative bias: a steep face must not see through a thin surface
        // in front of it.
        vec2 grad = f.xy * u_ray.xy;
        float raster = min((abs(grad.x) + abs(grad.y)) * u_tol_px, want * u_fallback_rel);
        float tol = want * u_tol_rel + u_tol_abs + raster;
        if (stored > want + tol) return false;
        // The texel holds this plane (or something behind it that the plane does not rise
        // past the spine to reach): visible.
        if (stored >= want - tol || want <= line_inv + line_inv * u_fallback_rel) return true;
        // Else the texel holds something well behind the plane, and the plane rises toward
        // the eye between the spine and the texel centre: it may be extrapolated past the
        // face's far side (a rafter's flank narrower than that distance, rising through the
        // roof it lies under).
    }
    // What the texel holds, carried back to the spine point along its own slope, against the
    // spine: so a surface just beyond the edge counts by its depth at the edge, not a pixel
    // away (a thin roof over a rafter's flank hides it, a floor sloping away behind a
    // silhouette does not). One place for both cases: llvmpipe runs every branch's code for
    // every sample, so each copy of this extrapolation cost it whether taken or not (its
    // neighbours come with the texel's own gathers, stored_inv_depth_cross).
    return stored_inv_depth_at(t, spine_px, stored, around) <=
           line_inv + line_inv * (u_tol_rel + u_fallback_rel) + u_tol_abs;
}

bool spine_visible(vec2 spine_px, float line_inv, vec3 edge_plane, vec3 face_pos, vec3 face_neg,
                   vec2 nudge) {
    if (!u_occlusion) return true;
    return sample_visible(ivec2(floor(spine_px + nudge)), spine_px, line_inv,
                          EdgeFaces(edge_plane, face_pos, face_neg));
}
