#version 450 core
// A layer after the first of depth peeling (pass_occlusion_layers.cpp, which culls back faces):
// only surfaces facing the eye clearly behind the layer before at this pixel, so layer k holds
// the (k+1)-th nearest surface facing the eye. A line point's occlusion level is the
// number of layers in front of it (occlusion_level.glsl).
//
// Facing is the rasteriser's: a triangle is front-facing when its window-space winding is
// counter-clockwise, which for points in front of the eye is the sign of dot(n, -p) in view
// space, the reference's definition (src/geometry/reference/reference.h), mirrored instances
// included.
layout(binding = TEXTURE_UNIT_PEEL_PREVIOUS) uniform sampler2D u_previous;
uniform float u_proj_a;        // stored depth -> inverse view depth: (ndc + a) * inv_b
uniform float u_proj_inv_b;
uniform bool u_depth_zero_to_one;
uniform float u_peel_rel;      // how much farther, relative, a surface must be to count apart

float inv_depth(float d) {
    float ndc = u_depth_zero_to_one ? d : 2.0 * d - 1.0;
    return (ndc + u_proj_a) * u_proj_inv_b;
}

void main() {
    if (!gl_FrontFacing) discard;  // culled already; kept so the rule reads here whole
    float previous = inv_depth(texelFetch(u_previous, ivec2(gl_FragCoord.xy), 0).r);
    // Inverse depth falls with distance; the cleared layer holds 1/far, which nothing passes.
    if (!(inv_depth(gl_FragCoord.z) < previous * (1.0 - u_peel_rel))) discard;
}
