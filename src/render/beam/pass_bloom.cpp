#include "render/passes.h"

namespace bz::render {

namespace {

// The first downsample, from the full-resolution picture into the first level, also marking
// the lit blocks (Targets::lit); with the phosphor, it glows from its own block phosphor.
void first_downsample(const PassContext& ctx, const gl::Texture2D& source,
                      const PhosphorStep* phosphor, float threshold) {
    const Targets& t = ctx.targets;
    (phosphor ? t.first_down_phosphor_fbo[static_cast<std::size_t>(phosphor->block_to)]
              : t.first_down_fbo)
        .bind();
    const gl::Program& down = phosphor
                                  ? ctx.programs.bloom_down_phosphor[phosphor->power_law ? 1 : 0]
                                  : ctx.programs.bloom_down;
    down.use();
    down.set("u_source", 0);
    down.set("u_factor", static_cast<int>(ctx.settings.bloom_resolution));
    down.set("u_threshold", threshold);
    down.set("u_knee", ctx.settings.beam.bloom_knee);
    source.bind(0);
    if (phosphor) {
        down.set("u_history_box", 1);
        set_phosphor_uniforms(down, *phosphor);
        t.block_picture[static_cast<std::size_t>(1 - phosphor->block_to)].bind(1);
    }
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// Downsample to the bloom resolution, then a separable linear-sampled Gaussian: horizontal
// into bloom_b, vertical into bloom_out, encoded in 8 bits for the composite's cheap fetch.
void gaussian_bloom(const PassContext& ctx, const gl::Texture2D& source,
                    const PhosphorStep* phosphor) {
    Targets& t = ctx.targets;
    first_downsample(ctx, source, phosphor, ctx.settings.beam.bloom_threshold);

    const gl::Program& blur = ctx.programs.bloom_blur;  // kernel baked in (programs.cpp)
    blur.use();
    blur.set("u_source", 0);

    t.bloom_b_fbo.bind();
    blur.set("u_encode", 0);
    blur.set("u_direction", glm::vec2(1.0f, 0.0f));
    t.bloom_a.bind(0);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    t.bloom_out_fbo.bind();
    blur.set("u_encode", 1);
    blur.set("u_floor", ctx.settings.beam.bloom_floor);
    blur.set("u_direction", glm::vec2(0.0f, 1.0f));
    t.bloom_b.bind(0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// MAME's bloom: a chain of levels, each half the size of the one before, summed with a
// weight per level (BeamSettings::mip_weights). Wide, soft glow for little work: the levels
// past the first cost a fraction of one full-resolution pass together.
void mip_chain_bloom(const PassContext& ctx, const gl::Texture2D& source,
                     const PhosphorStep* phosphor) {
    Targets& t = ctx.targets;
    const auto& w = ctx.settings.beam.mip_weights;
    const std::size_t n = t.bloom_mips.size();
    // Only the first level filters by brightness; the rest downsample what it kept.
    first_downsample(ctx, source, phosphor, ctx.settings.beam.bloom_threshold);
    const gl::Program& down = ctx.programs.bloom_down;
    down.use();
    down.set("u_source", 0);
    down.set("u_factor", 2);
    down.set("u_threshold", 0.0f);
    down.set("u_knee", ctx.settings.beam.bloom_knee);
    for (std::size_t k = 1; k < n; ++k) {
        t.bloom_mip_fbos[k].bind();
        t.bloom_mips[k - 1].bind(0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    float total = 0.0f;
    for (std::size_t k = 0; k < n; ++k) total += mip_weight(w, k);
    const gl::Program& up = ctx.programs.bloom_up;
    up.use();
    up.set("u_coarser", 0);
    up.set("u_level", 1);
    up.set("u_final", 0);
    gl::PipelineState add;
    add.blend = gl::Blend::add;
    gl::apply(add);
    for (std::size_t k = n - 1; k-- > 1;) {  // levels n-2 .. 1
        t.bloom_mip_fbos[k].bind();
        up.set("u_ratio", mip_weight(w, k + 1) / mip_weight(w, k));
        t.bloom_mips[k + 1].bind(0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl::apply(gl::PipelineState{});
    t.bloom_out_fbo.bind();
    up.set("u_final", 1);
    up.set("u_floor", ctx.settings.beam.bloom_floor);
    up.set("u_ratio", n > 1 ? mip_weight(w, 1) / mip_weight(w, 0) : 0.0f);
    up.set("u_weight", mip_weight(w, 0) / total);
    t.bloom_mips[n > 1 ? 1 : 0].bind(0);
    t.bloom_mips[0].bind(1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace

float mip_weight(const std::vector<float>& weights, std::size_t level) {
    // A zero weight would break the chain's ratios; a tiny one switches the level off.
    return level < weights.size() ? std::max(weights[level], 1e-4f) : 1e-4f;
}

void pass_bloom(const PassContext& ctx, const gl::Texture2D& source, const PhosphorStep* phosphor) {
    gl::apply(gl::PipelineState{});
    ctx.empty_vao.bind();
    if (ctx.settings.beam.bloom == BloomKind::mip_chain && !ctx.targets.bloom_mips.empty()) {
        mip_chain_bloom(ctx, source, phosphor);
    } else {
        gaussian_bloom(ctx, source, phosphor);
    }
}

}  // namespace bz::render
