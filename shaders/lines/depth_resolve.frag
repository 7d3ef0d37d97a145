#version 450 core
// The compute prepass's depth (prepass_raster.comp) into the depth buffer, under the depth
// test the prepass draws with (nearer wins), so it merges with the triangles the pipeline drew.
layout(binding = IMAGE_UNIT_RASTER_DEPTH, r32ui) uniform readonly uimage2D u_depth;

void main() {
    uint bits = imageLoad(u_depth, ivec2(gl_FragCoord.xy)).r;
    if (bits == 0u) discard;  // no small triangle covers this pixel's centre
    gl_FragDepth = uintBitsToFloat(bits);
}
