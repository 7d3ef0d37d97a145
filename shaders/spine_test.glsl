// The spine test (Cole & Finkelstein): a line fragment is visible when the point of the spine
// nearest to it is not behind the prepass depth. Every fragment across the line's width asks
// about the same spine point, so a line ends cleanly where it goes behind something.
//
// The depth a sample pixel should hold if the edge is unoccluded is not the spine's depth but
// the depth of the face the pixel centre lands on, which differs by the face's slope (large at
// grazing angles). So each edge carries the planes of its faces: the pixel's side of the
// eye-edge plane picks the face, and the depth of that plane along the pixel's ray is exact.
uniform sampler2D u_depth;
uniform bool u_occlusion;     // false in the arcade style: the 1980 machine hid nothing
uniform int u_spine_samples;  // 1 or 9
uniform float u_proj_a;       // projection terms that turn stored depth back into view depth
uniform float u_proj_b;
uniform bool u_depth_zero_to_one;
uniform float u_depth_bias;   // relative
uniform mat4 u_proj;
uniform vec2 u_viewport;

float stored_view_depth(ivec2 texel) {
    ivec2 size = textureSize(u_depth, 0);
    float d = texelFetch(u_depth, clamp(texel, ivec2(0), size - 1), 0).r;
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    float v = u_proj_b / (ndc + u_proj_a);
    return v > 0.0 ? v : 1e30;  // cleared depth maps to the far plane; guard the division
}

vec3 pixel_ray(vec2 px) {
    vec2 ndc = px / u_viewport * 2.0 - 1.0;
    return vec3(ndc.x / u_proj[0][0], ndc.y / u_proj[1][1], -1.0);
}

// View depth the unoccluded edge's own surface has at texel `t`.
float expected_depth(ivec2 t, float line_depth, vec3 edge_plane, vec4 face_pos, vec4 face_neg) {
    vec3 r = pixel_ray(vec2(t) + 0.5);
    vec4 f = dot(edge_plane, r) >= 0.0 ? face_pos : face_neg;
    float denom = dot(f.xyz, r);
    if (f.xyz == vec3(0.0) || abs(denom) < 1e-30) return line_depth;
    float v = f.w / denom;
    // A plane seen edge-on can put its depth anywhere; trust it only near the spine's depth.
    return (v > 0.0 && v < line_depth * 4.0) ? v : line_depth;
}

bool sample_visible(ivec2 t, float line_depth, vec3 edge_plane, vec4 face_pos, vec4 face_neg) {
    float want = expected_depth(t, line_depth, edge_plane, face_pos, face_neg);
    return want * (1.0 - u_depth_bias) <= stored_view_depth(t);
}

bool spine_visible(vec2 spine_px, float line_depth, vec3 edge_plane, vec4 face_pos, vec4 face_neg,
                   vec2 nudge) {
    if (!u_occlusion) return true;
    ivec2 base = ivec2(floor(spine_px + nudge));
    if (u_spine_samples <= 1) return sample_visible(base, line_depth, edge_plane, face_pos, face_neg);
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            if (sample_visible(base + ivec2(x, y), line_depth, edge_plane, face_pos, face_neg)) return true;
        }
    }
    return false;
}
