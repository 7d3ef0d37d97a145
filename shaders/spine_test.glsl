// The spine test (Cole & Finkelstein): a line fragment is visible when the point of the spine
// nearest to it is not behind the prepass depth. Every fragment across the line's width asks
// about the same spine point, so a line ends cleanly where it goes behind something.
//
// The depth a sample pixel should hold if the edge is unoccluded is not the spine's depth but
// the depth of the face the pixel centre lands on, which differs by the face's slope (large at
// grazing angles). So each edge carries the planes of its faces: the pixel's side of the
// eye-edge plane picks the face, and that plane's depth along the pixel's ray is exact.
//
// Everything is compared as inverse view depth (1/v), which is affine in the stored depth and
// in a plane's equation, so the test needs no division: for a plane n.X = 1 (n pre-divided by
// n.p in the geometry shader) and the ray r = (x, y, -1) through a pixel, 1/v = n.r.
uniform sampler2D u_depth;
uniform bool u_occlusion;     // false in the arcade style: the 1980 machine hid nothing
uniform int u_spine_samples;  // 1 or 9
uniform float u_proj_a;       // stored depth -> inverse view depth: (ndc + a) * inv_b
uniform float u_proj_inv_b;
uniform bool u_depth_zero_to_one;
uniform float u_bias_scale;   // 1 / (1 - relative view-space depth bias)
uniform vec4 u_ray;           // pixel -> view ray: xy = pixel * u_ray.xy + u_ray.zw, z = -1
uniform ivec2 u_depth_max;    // depth texture size - 1

float stored_inv_depth(ivec2 texel) {
    float d = texelFetch(u_depth, clamp(texel, ivec2(0), u_depth_max), 0).r;
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    return (ndc + u_proj_a) * u_proj_inv_b;  // cleared depth gives 1/far: nothing in front
}

// Inverse depth the unoccluded edge's own surface has at texel `t`.
float expected_inv_depth(ivec2 t, float line_inv, vec3 edge_plane, vec3 face_pos, vec3 face_neg) {
    vec3 r = vec3((vec2(t) + 0.5) * u_ray.xy + u_ray.zw, -1.0);
    vec3 f = dot(edge_plane, r) >= 0.0 ? face_pos : face_neg;
    float inv = dot(f, r);
    // No face on that side (all zero), or a plane seen so edge-on that its depth could be
    // anywhere: fall back to the spine's own depth.
    return (inv > line_inv * 0.25) ? inv : line_inv;
}

bool sample_visible(ivec2 t, float line_inv, vec3 edge_plane, vec3 face_pos, vec3 face_neg) {
    // want * (1 - bias) <= stored  <=>  1/stored <= (1/want) / (1 - bias)
    return stored_inv_depth(t) <= expected_inv_depth(t, line_inv, edge_plane, face_pos, face_neg) * u_bias_scale;
}

bool spine_visible(vec2 spine_px, float line_inv, vec3 edge_plane, vec3 face_pos, vec3 face_neg,
                   vec2 nudge) {
    if (!u_occlusion) return true;
    ivec2 base = ivec2(floor(spine_px + nudge));
    if (u_spine_samples <= 1) return sample_visible(base, line_inv, edge_plane, face_pos, face_neg);
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            if (sample_visible(base + ivec2(x, y), line_inv, edge_plane, face_pos, face_neg)) return true;
        }
    }
    return false;
}
