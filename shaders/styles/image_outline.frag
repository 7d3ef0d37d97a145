#version 450 core
// Image-space outline baseline: Sobel on linear view depth and on face normals. A pixel on a
// surface is an edge pixel when the depth gradient is large relative to its own depth (an
// occluding contour: only the nearer side qualifies, the background never does) or when the
// normal gradient exceeds the step a crease of the crease angle makes.
layout(binding = TEXTURE_UNIT_DEPTH) uniform sampler2D u_depth;
layout(binding = TEXTURE_UNIT_NORMALS) uniform sampler2D u_normals;  // n * 0.5 + 0.5; alpha 0 on the background
uniform float u_proj_a;
uniform float u_proj_b;
uniform bool u_depth_zero_to_one;
uniform float u_depth_threshold;   // relative depth step per pixel
uniform float u_normal_threshold;  // |n1 - n2| = 2 sin(angle / 2) at the crease angle
uniform vec3 u_color;

layout(location = 0) out vec4 o_color;

const float kBackground = 1e30;

float view_depth(ivec2 t) {
    float d = texelFetch(u_depth, t, 0).r;
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    float v = u_proj_b / (ndc + u_proj_a);
    return v > 0.0 ? min(v, kBackground) : kBackground;
}

vec3 normal_at(ivec2 t) {
    vec4 n = texelFetch(u_normals, t, 0);
    return n.a > 0.0 ? n.xyz * 2.0 - 1.0 : vec3(0.0);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float centre = view_depth(p);
    if (centre >= kBackground) discard;
    // The 3x3 neighbourhood, clamped at the image border.
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, textureSize(u_depth, 0) - 1);
    ivec2 t00 = lo, t10 = ivec2(p.x, lo.y), t20 = ivec2(hi.x, lo.y);
    ivec2 t01 = ivec2(lo.x, p.y), t21 = ivec2(hi.x, p.y);
    ivec2 t02 = ivec2(lo.x, hi.y), t12 = ivec2(p.x, hi.y), t22 = hi;
    float d00 = view_depth(t00), d10 = view_depth(t10), d20 = view_depth(t20);
    float d01 = view_depth(t01), d21 = view_depth(t21);
    float d02 = view_depth(t02), d12 = view_depth(t12), d22 = view_depth(t22);
    float gx = (d20 + 2.0 * d21 + d22) - (d00 + 2.0 * d01 + d02);
    float gy = (d02 + 2.0 * d12 + d22) - (d00 + 2.0 * d10 + d20);
    // A unit step gives a Sobel response of 4.
    bool edge = 0.25 * length(vec2(gx, gy)) > u_depth_threshold * centre;
    if (!edge) {
        vec3 n00 = normal_at(t00), n10 = normal_at(t10), n20 = normal_at(t20);
        vec3 n01 = normal_at(t01), n21 = normal_at(t21);
        vec3 n02 = normal_at(t02), n12 = normal_at(t12), n22 = normal_at(t22);
        vec3 nx = (n20 + 2.0 * n21 + n22) - (n00 + 2.0 * n01 + n02);
        vec3 ny = (n02 + 2.0 * n12 + n22) - (n00 + 2.0 * n10 + n20);
        edge = 0.25 * sqrt(dot(nx, nx) + dot(ny, ny)) > u_normal_threshold;
    }
    if (!edge) discard;
#ifdef MASK_MODE
    o_color = vec4(1.0);
#else
    o_color = vec4(u_color, 1.0);
#endif
}
