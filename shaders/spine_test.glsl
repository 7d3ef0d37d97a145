// The spine test (Cole & Finkelstein): a line fragment is visible when the point of the
// spine nearest to it is not behind the prepass depth. Every fragment across the line's width
// asks about the same spine point, so a line ends cleanly where it goes behind something.
uniform sampler2D u_depth;
uniform bool u_occlusion;     // false in the arcade style: the 1980 machine hid nothing
uniform int u_spine_samples;  // 1 or 9
uniform float u_proj_a;       // projection terms that turn stored depth back into view depth
uniform float u_proj_b;
uniform bool u_depth_zero_to_one;

float view_depth_at(ivec2 texel) {
    ivec2 size = textureSize(u_depth, 0);
    float d = texelFetch(u_depth, clamp(texel, ivec2(0), size - 1), 0).r;
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    float denom = ndc + u_proj_a;
    return denom > 0.0 ? u_proj_b / denom : 1e30;  // cleared depth: nothing there
}

bool spine_visible(vec2 spine_px, float line_depth, float slack, vec2 nudge) {
    if (!u_occlusion) return true;
    float limit = line_depth * (1.0 - slack);
    vec2 base = spine_px + nudge;
    if (u_spine_samples <= 1) return limit <= view_depth_at(ivec2(floor(base)));
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            if (limit <= view_depth_at(ivec2(floor(base)) + ivec2(x, y))) return true;
        }
    }
    return false;
}
