// The beam's shape from a line's intensity, shared by every stage that extrudes lines
// (lines.geom, hud.geom, and any other line path): MAME's vector renderer
// (src/emu/video/vector.cpp) plus beam dwell and overdrive defocus. The uniforms are set by
// render/beam/beam_uniforms.cpp (set_beam_uniforms); the look's knobs are render::BeamSettings.
#include "beam_ends.glsl"

uniform vec4 u_beam_width;  // x, y: min and max half-width (px, this target); z: sigmoid weight;
                            // w: the MAME intensity (0..1) of a line of intensity 1
uniform vec4 u_beam_shape;  // x: flicker; y: dwell length (px); z: dwell's largest gain;
                            // w: defocus per unit of intensity above MAME's 1
uniform uint u_beam_seed;   // the frame's flicker seed (FrameList::seed)

struct BeamShape {
    float half_width;  // pixels
    float gain;        // on the line's colour, which already carries its intensity
    float softness;    // 1: the normal profile; below 1: flatter (an overdriven, defocused spot)
};

// MAME's normalized tunable sigmoid (after Dino Dini), for n and k in [-1, 1]: k = 0 is
// linear, k > 0 keeps the beam thin until the intensity nears its top.
float beam_sigmoid(float n, float k) { return (n - n * k) / (k - abs(n) * 2.0 * k + 1.0); }

// A uniform number in [0, 1) from the line's key and the frame's seed (an integer hash):
// the same frame always flickers the same way, so replays and benchmarks repeat.
float beam_random(uint key) {
    uint x = key * 0x9e3779b9u ^ u_beam_seed;
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return float(x >> 8) * (1.0 / 16777216.0);
}

// `intensity`: the line's (1 = normal); `length_px`: its length on screen; `key`: any number
// that tells this line from the others in the frame (for flicker).
BeamShape beam_shape(float intensity, float length_px, uint key) {
    // Flicker, as MAME does it: intensity -= intensity * random * flicker.
    float flicker = 1.0 - u_beam_shape.x * beam_random(key);
    float n = max(intensity * flicker, 0.0) * u_beam_width.w;
    // Overdrive: past full intensity the spot grows instead of the brightness clipping.
    float spread = 1.0 + u_beam_shape.w * max(n - 1.0, 0.0);
    float sig = beam_sigmoid(min(n, 1.0), u_beam_width.z);
    // Dwell: the beam settles on every vector for a fixed time, worth `dwell` pixels of
    // drawing; spread over a short vector's length that is more energy per pixel.
    float dwell = u_beam_shape.y > 0.0
                      ? min((length_px + u_beam_shape.y) / max(length_px, 1e-3), u_beam_shape.z)
                      : 1.0;
    BeamShape b;
    b.half_width = mix(u_beam_width.x, u_beam_width.y, sig) * spread;
    b.gain = flicker * max(dwell, 1.0) / spread;
    b.softness = 1.0 / spread;
    return b;
}
