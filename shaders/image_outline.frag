#version 450 core
// Image-space outline baseline: Sobel on linear view depth and on face normals. A pixel on a
// surface is an edge pixel when the depth gradient is large relative to its own depth (an
// occluding contour: only the nearer side qualifies, the background never does) or when the
// normal gradient exceeds the step a crease of the crease angle makes.
uniform sampler2D u_depth;
uniform sampler2D u_normals;
uniform float u_proj_a;
uniform float u_proj_b;
uniform bool u_depth_zero_to_one;
uniform float u_depth_threshold;   // relative depth step per pixel
uniform float u_normal_threshold;  // |n1 - n2| = 2 sin(angle / 2) at the crease angle
uniform vec3 u_color;

layout(location = 0) out vec4 o_color;

const float kBackground = 1e30;

float view_depth(ivec2 texel) {
    ivec2 size = textureSize(u_depth, 0);
    float d = texelFetch(u_depth, clamp(texel, ivec2(0), size - 1), 0).r;
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    float v = u_proj_b / (ndc + u_proj_a);
    return v > 0.0 ? min(v, kBackground) : kBackground;
}

vec3 normal_at(ivec2 texel) {
    ivec2 size = textureSize(u_normals, 0);
    return texelFetch(u_normals, clamp(texel, ivec2(0), size - 1), 0).xyz;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float centre = view_depth(p);
    if (centre >= kBackground) discard;
    // Sobel weights for the 3x3 neighbourhood, row by row from the bottom-left.
    const float wx[9] = float[9](-1.0, 0.0, 1.0, -2.0, 0.0, 2.0, -1.0, 0.0, 1.0);
    const float wy[9] = float[9](-1.0, -2.0, -1.0, 0.0, 0.0, 0.0, 1.0, 2.0, 1.0);
    float gx = 0.0, gy = 0.0;
    vec3 nx = vec3(0.0), ny = vec3(0.0);
    for (int k = 0; k < 9; ++k) {
        ivec2 t = p + ivec2(k % 3 - 1, k / 3 - 1);
        float d = view_depth(t);
        vec3 n = normal_at(t);
        gx += wx[k] * d;
        gy += wy[k] * d;
        nx += wx[k] * n;
        ny += wy[k] * n;
    }
    // A unit step gives a Sobel response of 4.
    bool depth_edge = 0.25 * length(vec2(gx, gy)) > u_depth_threshold * centre;
    bool normal_edge = 0.25 * sqrt(dot(nx, nx) + dot(ny, ny)) > u_normal_threshold;
    if (!depth_edge && !normal_edge) discard;
#ifdef MASK_MODE
    o_color = vec4(1.0);
#else
    o_color = vec4(u_color, 1.0);
#endif
}
