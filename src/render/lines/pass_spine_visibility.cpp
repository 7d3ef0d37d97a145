#include <algorithm>

#include "render/passes.h"

namespace bz::render {

namespace {

// Work groups of the visibility dispatch (8 invocations each, spine_visibility.comp); each
// takes every n-th record. A fixed count rather than one group per record: llvmpipe sets up
// each group's invocations anew, which costs as much as the spine tests of a short edge.
// Measured on llvmpipe (800x600, Bernardoni 2018's hallway / Suzanne): 32 invocations per group
// 8.0 / 3.3 ms, 8 invocations 4.6 / 1.4 ms; 128 or 1024 groups the same within the noise.
// 1024 groups keep 8192 invocations busy on a GPU. A small frame gets fewer: about one group
// per two records of the frame before (any count is correct, groups stride over the records),
// since every group costs llvmpipe a start-up even when it finds no record.
constexpr GLuint kMaxVisibilityGroups = 1024;
constexpr GLuint kMinVisibilityGroups = 16;

}  // namespace

// Every style whose mask is the exact line mask takes it from the samples (the filled styles'
// strokes do not read them, but their masks must equal the vector style's).
bool wants_spine_samples(const PassContext& ctx) {
    return ctx.settings.spine_sample_spacing_px > 0.0f && ctx.occlusion &&
           ctx.settings.method == LineMethod::compute && ctx.style.lines != LinePass::sketch;
}

// LineMethod::compute, between the edges pass and the quads: the spine test once per spine
// sample of every record (spine_visibility.comp) instead of once per line fragment.
void pass_spine_visibility(const PassContext& ctx) {
    if (!wants_spine_samples(ctx)) return;  // no samples reserved: the fragments test
    const EdgeStorage& edges = ctx.edges;
    const gl::Program& program = ctx.programs.spine_visibility;
    program.use();
    set_line_uniforms(program, ctx);
    program.set("u_capacity", edges.capacity());
    program.set("u_sample_capacity", edges.sample_capacity());
    ctx.targets.depth.bind(kTextureUnitDepth);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCommandBinding, edges.command().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, edges.records().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSamplesBinding, edges.samples().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSpansBinding, edges.spans().id());
    // A fixed number of groups, each reading the appended count itself: no indirect dispatch,
    // no read-back.
    const std::size_t previous = edges.previous().vertex_count / kVerticesPerEdge;
    glDispatchCompute(static_cast<GLuint>(std::clamp<std::size_t>(
                          previous / 2, kMinVisibilityGroups, kMaxVisibilityGroups)),
                      1, 1);
    // The quad pass reads the samples in its fragments, the spans in its vertices and its two
    // draws' counts as indirect commands.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace bz::render
