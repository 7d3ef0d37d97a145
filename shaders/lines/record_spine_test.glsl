// The spine test (spine_test.glsl) of an edge-buffer record (edge_record.glsl) at parameter t
// of its spine, as spine_visibility.comp runs it per spine sample and edge_quad.frag per
// fragment for a record without samples. Needs edge_geometry.glsl and spine_test.glsl first.

// Where a record's depth sample is taken from its spine: a silhouette's just outside its
// front face (edge_geometry.glsl), others' on the spine. The same for every t: compute once.
vec2 record_nudge(EdgeRecord r) {
    vec2 dir, nrm;
    spine_frame(r.screen.xy, r.screen.zw, dir, nrm);
    bool silhouette = (r.ids.x & EDGE_KIND_MASK) == EDGE_SILHOUETTE;
    return silhouette ? silhouette_nudge(r.edge_plane.xyz, r.screen.xy, nrm) : vec2(0.0);
}

bool record_spine_visible(EdgeRecord r, float t, vec2 nudge) {
    vec2 spine = mix(r.screen.xy, r.screen.zw, t);
    float line_inv = mix(r.depth.x, r.depth.y, t);  // 1/depth is affine on screen
    return spine_visible(spine, line_inv, r.edge_plane.xyz, r.face_pos.xyz, r.face_neg.xyz, nudge);
}
