// Beam ends, lengthened as MAME does it: src/emu/video/vector.cpp moves both end points of every
// vector outward by 3/8 of the beam's full width ("extend vector line by 3/8 beam_width on both
// sides"; a zero-length vector, a dot, gets the same on both sides). MAME's line quads have
// square ends, so this closes the gaps where vectors meet; beamzone's beam already has a round,
// fading cap of one half-width, and the lengthening comes on top of it.
//
// It is visual only. The quad reaches further (beam_end_reach, for lines.geom, edge_quad.vert
// and hud.geom) and the beam's profile is measured from the lengthened spine (beam_distance,
// for the fragment stages), but the spine test still asks about the nearest point of the
// edge's own, unlengthened spine: a fragment past an end point shows exactly when that end
// point is visible. So a lengthened end never shows a part of an edge that is hidden (the end
// of an edge that runs behind a wall stays behind it), and the accuracy mask, which marks only
// the pixels the true spine crosses, does not change; u_beam_lengthen is 0 there anyway
// (render/beam/beam_uniforms.cpp).
//
// Every end is lengthened, also where an edge was clipped (near and far plane, guard band) and
// where it meets other lines:
//  - a clipped end is not a real end, but the edge does go on past it in the same screen
//    direction (past the near plane toward the screen's edge, past the far plane toward its
//    vanishing point), so the longer beam draws where the edge is; guard-band ends lie outside
//    the picture;
//  - where lines meet, MAME's overlap is the point: with additive blending the joints of a
//    polyline glow a little brighter, as where a real beam turns.
#ifndef BEAM_ENDS_GLSL
#define BEAM_ENDS_GLSL

uniform float u_beam_lengthen;  // share of the beam's full width added at each end (MAME: 3/8)

// How far past each end point the beam is lengthened (px), for a beam of this half-width.
float beam_end_lengthening(float half_width) { return 2.0 * u_beam_lengthen * half_width; }

// How far past each end point a line's quad must reach: the lengthening plus the round cap.
float beam_end_reach(float half_width) { return half_width + beam_end_lengthening(half_width); }

// The distance from p to the spine a-b lengthened at both ends (along the x axis for a dot, as
// edge_geometry.glsl's spine_frame orients one). `spine` is p's nearest point on the
// unlengthened spine, which is all that is needed when nothing is lengthened.
float beam_distance(vec2 p, vec2 a, vec2 b, vec2 spine, float half_width) {
    float e = beam_end_lengthening(half_width);
    if (e <= 0.0) return distance(p, spine);
    vec2 d = b - a;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    return distance(p, a + dir * clamp(dot(p - a, dir), -e, len + e));
}

#endif
