// Spine samples (LineMethod::compute). The spine test (spine_test.glsl) asks about the spine
// point nearest to a fragment, so every fragment across a beam's width repeats the question
// its neighbours asked. Instead, the spine-visibility pass (spine_visibility.comp) answers it
// once per sample along each edge's spine, at most RenderSettings::spine_sample_spacing_px
// apart, and the line fragments look the answer up for the sample nearest to their spine
// point. At 1 px a sample's spine point lies within half a pixel of the fragment's, so a line
// ends where it goes behind something to within that (bench --accuracy: the same F1 as the
// test in every fragment).

// Samples for a spine from s0 to s1 (window pixels): both ends and at most `spacing` apart.
uint spine_sample_count(vec2 s0, vec2 s1, float spacing) {
    return uint(ceil(length(s1 - s0) / spacing)) + 1u;
}

// The sample nearest to parameter t (0..1) on a spine of `count` samples.
uint spine_sample_index(float t, uint count) {
    return min(uint(t * float(count - 1u) + 0.5), count - 1u);
}

// Where sample k lies on the spine (0..1).
float spine_sample_t(uint k, uint count) { return count > 1u ? float(k) / float(count - 1u) : 0.0; }
