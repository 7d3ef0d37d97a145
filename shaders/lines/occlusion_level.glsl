// A line point's occlusion level (technical, vector-xray): how many surfaces facing the eye lie
// in front of it, capped at the layers peeled (pass_occlusion_layers.cpp, kOcclusionLayers =
// geo::kMaxOcclusionLevel), the definition of the exact reference
// (src/geometry/reference/reference.h). Include after spine_test.glsl: it reads the same
// texel the spine test samples (the silhouette's nudge included) and compares each layer with
// the edge's own face plane there, with the spine test's tolerances, so the edge's own faces
// never count. Layers are sorted front to back: counting stops at the first one not in front.
layout(binding = TEXTURE_UNIT_OCCLUSION_LAYER0) uniform sampler2D u_layer0;
layout(binding = TEXTURE_UNIT_OCCLUSION_LAYER1) uniform sampler2D u_layer1;
layout(binding = TEXTURE_UNIT_OCCLUSION_LAYER2) uniform sampler2D u_layer2;

float layer_inv_depth(int layer, ivec2 t) {
    float d = layer == 0 ? texelFetch(u_layer0, t, 0).r
                         : (layer == 1 ? texelFetch(u_layer1, t, 0).r : texelFetch(u_layer2, t, 0).r);
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    return (ndc + u_proj_a) * u_proj_inv_b;  // cleared: 1/far, never in front
}

int occlusion_level(vec2 spine_px, float line_inv, EdgeFaces e, vec2 nudge) {
    ivec2 t = clamp(ivec2(floor(spine_px + nudge)), ivec2(0), u_depth_max);
    vec3 r = vec3((vec2(t) + 0.5) * u_ray.xy + u_ray.zw, -1.0);
    vec3 f = dot(e.edge_plane, r) >= 0.0 ? e.face_pos : e.face_neg;
    float want = dot(f, r);
    float tol;
    if (!(want > line_inv * 0.25)) {
        // No usable face on that side: the spine's own depth, as the spine test's fallback.
        want = line_inv;
        tol = line_inv * (u_tol_rel + u_fallback_rel) + u_tol_abs;
    } else {
        vec2 grad = f.xy * u_ray.xy;
        tol = want * u_tol_rel + u_tol_abs +
              min((abs(grad.x) + abs(grad.y)) * u_tol_px, want * u_fallback_rel);
    }
    int level = 0;
    for (int k = 0; k < 3; ++k) {
        if (!(layer_inv_depth(k, t) > want + tol)) break;
        ++level;
    }
    return level;
}
