#include <array>
#include <cmath>
#include <utility>

#include "render/clear_image.h"
#include "render/passes.h"

namespace bz::render {

namespace {

// Whether this frame's bloom marks the lit tiles (Targets::lit_tiles) for the sparse composite.
bool marks_tiles(const PassContext& ctx) {
    return ctx.targets.lit_tiles && ctx.settings.sparse_composite;
}

// The first downsample, from this frame's beam image into the first level, also marking the
// lit-tile under each lit block (shaders/beam/lit_tiles.glsl; the marks are cleared first).
// With the beam's tile marks (Targets::beam_tiles), only under the marked tiles: a block reads
// only its own pixels, so every other block is black, which the clear writes; on llvmpipe
// this pass reading every pixel cost about 2 ms at 1280x720.
void first_downsample(const PassContext& ctx, const gl::Texture2D& source, float threshold) {
    Targets& t = ctx.targets;
    const bool mark = marks_tiles(ctx);
    // The beam's tile marks, where this frame's line pass made them (not the image outline's)
    // and the frame wants them (RenderSettings::first_downsample).
    const bool sparse =
        frame_wrote(ctx, Resource::beam_tiles) && mark && !ctx.dense_first_downsample;
    if (ctx.stats) {
        ctx.stats->first_downsample =
            sparse ? FirstDownsampleRead::marked_tiles : FirstDownsampleRead::whole_image;
    }
    if (mark) glClearTexImage(t.lit_tiles.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    t.first_down_fbo.bind();
    const gl::Texture2D& level = t.bloom_mips.empty() ? t.bloom_a : t.bloom_mips[0];
    if (sparse) clear_colour(ctx, level, glm::vec4(0.0f));
    const gl::Program& down = sparse ? ctx.programs.bloom_down_tiles : ctx.programs.bloom_down;
    down.use();
    bind_lit_tile_marks(down, t, mark);
    down.set("u_inv_target", 1.0f / glm::vec2(t.first_down_fbo.width(), t.first_down_fbo.height()));
    down.set("u_factor", static_cast<int>(ctx.settings.bloom_resolution));
    down.set("u_threshold", threshold);
    down.set("u_knee", ctx.settings.beam.bloom_knee);
    source.bind(kTextureUnitSource);
    if (!sparse) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        return;
    }
    draw_tile_quads(down, t.beam_tiles, glm::ivec2(t.width, t.height));
}

// The program of the bloom's last step, which writes the finished bloom: with the phosphor,
// the variant that keeps last frame's glow, decayed (glow_persistence.glsl).
const gl::Program& last_step(const PassContext& ctx, const gl::Program& plain,
                             const gl::Program& glow, const PhosphorStep* phosphor) {
    if (!phosphor) {
        plain.use();
        return plain;
    }
    glow.use();
    // A history from before a frame without bloom is stale: start from black.
    glow.set("u_glow_sqrt_factor",
             ctx.history.holds(Resource::glow) ? std::sqrt(phosphor->glow_factor) : 0.0f);
    ctx.history.glow.bind(kTextureUnitGlowLast);
    return glow;
}

// The last step writes the finished bloom and marks the lit tiles its light reaches.
void set_last_step_marks(const PassContext& ctx, const gl::Program& last) {
    last.set("u_factor", static_cast<int>(ctx.settings.bloom_resolution));
    bind_lit_tile_marks(last, ctx.targets, marks_tiles(ctx));
}

// Downsample to the bloom resolution, then a separable linear-sampled Gaussian: horizontal
// into bloom_b, vertical into bloom_out, encoded in 8 bits for the composite's cheap fetch.
void gaussian_bloom(const PassContext& ctx, const gl::Texture2D& source,
                    const PhosphorStep* phosphor) {
    Targets& t = ctx.targets;
    first_downsample(ctx, source, ctx.settings.beam.bloom_threshold);

    const gl::Program& blur = ctx.programs.bloom_blur;  // kernel baked in (programs.cpp)
    blur.use();

    t.bloom_b_fbo.bind();
    blur.set("u_encode", 0);
    blur.set("u_direction", glm::vec2(1.0f, 0.0f));
    t.bloom_a.bind(kTextureUnitSource);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    t.bloom_out_fbo.bind();
    const gl::Program& last = last_step(ctx, blur, ctx.programs.bloom_blur_glow, phosphor);
    last.set("u_encode", 1);
    last.set("u_floor", ctx.settings.beam.bloom_floor);
    last.set("u_direction", glm::vec2(0.0f, 1.0f));
    set_last_step_marks(ctx, last);
    t.bloom_b.bind(kTextureUnitSource);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The first level the compute walk takes (BloomChain::compute): the first one past level 0
// of at most kMaxWalkTexels, or none (the pipeline draws every level). The walk runs on one
// thread of a software rasteriser; a larger level is drawn, on all of them. At 1280x720 a
// quarter-resolution level 1 (160x90) walked faster than drawn, a half-resolution one
// (320x180) 0.7-1.5 ms slower (docs/measurements/bloom-chain.md).
constexpr int kMaxWalkTexels = 128 * 128;
std::size_t first_walked_level(const PassContext& ctx) {
    const std::size_t n = ctx.targets.bloom_mips.size();
    bool walk = ctx.software_rasteriser;
    switch (ctx.settings.bloom_chain) {
        case BloomChain::pipeline:
            walk = false;
            break;
        case BloomChain::compute:
            walk = true;
            break;
        case BloomChain::automatic:
            break;
    }
    if (!walk) return n;
    for (std::size_t k = 1; k < n; ++k) {
        const gl::Texture2D& level = ctx.targets.bloom_mips[k];
        if (level.width() * level.height() <= kMaxWalkTexels) return k;
    }
    return n;
}

// Levels [first, end) downsampled by the GL pipeline, one draw each.
void down_by_draws(const PassContext& ctx, std::size_t first, std::size_t end) {
    Targets& t = ctx.targets;
    const gl::Program& down = ctx.programs.bloom_down;
    down.use();
    bind_lit_tile_marks(down, t, false);  // only the first level's blocks are screen pixels
    down.set("u_factor", 2);
    down.set("u_threshold", 0.0f);
    down.set("u_knee", ctx.settings.beam.bloom_knee);
    for (std::size_t k = first; k < end; ++k) {
        t.bloom_mip_fbos[k].bind();
        down.set("u_inv_target",
                 1.0f / glm::vec2(t.bloom_mip_fbos[k].width(), t.bloom_mip_fbos[k].height()));
        t.bloom_mips[k - 1].bind(kTextureUnitSource);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

// Levels from `from` down to 1 take the upsample of the level above them, one draw each,
// blended onto what they hold.
void up_by_draws(const PassContext& ctx, std::size_t from) {
    Targets& t = ctx.targets;
    const auto& w = ctx.settings.beam.mip_weights;
    const gl::Program& up = ctx.programs.bloom_up;
    up.use();
    up.set("u_final", 0);
    gl::PipelineState add;
    add.blend = gl::Blend::add;
    gl::apply(add);
    for (std::size_t k = from; k >= 1; --k) {
        t.bloom_mip_fbos[k].bind();
        up.set("u_ratio", mip_weight(w, k + 1) / mip_weight(w, k));
        t.bloom_mips[k + 1].bind(kTextureUnitCoarser);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl::apply(gl::PipelineState{});
}

// Levels [first, n) down and back up to `first` by one workgroup of bloom_chain.comp,
// through Targets::bloom_chain_texels; level `first` goes to its texture.
void walk_levels(const PassContext& ctx, std::size_t first) {
    Targets& t = ctx.targets;
    const auto& w = ctx.settings.beam.mip_weights;
    const std::size_t n = t.bloom_mips.size();
    std::array<glm::ivec2, kMaxBloomLevels> sizes{};
    std::array<int, kMaxBloomLevels> offsets{};  // into Targets::bloom_chain_texels
    std::array<float, kMaxBloomLevels> ratios{};
    int offset = 0;
    for (std::size_t k = 0; k < n; ++k) {
        sizes[k] = {t.bloom_mips[k].width(), t.bloom_mips[k].height()};
        if (k + 1 < n) ratios[k] = mip_weight(w, k + 1) / mip_weight(w, k);
        if (k < first) continue;
        offsets[k] = offset;
        offset += sizes[k].x * sizes[k].y;
    }
    const gl::Program& chain = ctx.programs.bloom_chain;
    chain.use();
    const int count = static_cast<int>(kMaxBloomLevels);
    chain.set("u_first", static_cast<int>(first));
    chain.set("u_levels", static_cast<int>(n));
    chain.set_array("u_size", sizes.data(), count);
    chain.set_array("u_offset", offsets.data(), count);
    chain.set_array("u_ratio", ratios.data(), count);
    t.bloom_mips[first - 1].bind(kTextureUnitSource);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBloomChainBinding, t.bloom_chain_texels.id());
    glBindImageTexture(kImageUnitBloomLevel, t.bloom_mips[first].id(), 0, GL_FALSE, 0,
                       GL_WRITE_ONLY, GL_RGBA16F);
    glDispatchCompute(1, 1, 1);
    // What follows samples level `first` (the draws up, or the last step).
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

// The chain's levels 1 .. n-1, down and back up to level 1: the larger levels drawn by the
// pipeline, the rest walked in one dispatch (first_walked_level).
void chain_past_level_zero(const PassContext& ctx) {
    const std::size_t n = ctx.targets.bloom_mips.size();
    const std::size_t walked = first_walked_level(ctx);
    if (ctx.stats) ctx.stats->bloom_chain = {.drawn = walked - 1, .walked = n - walked};
    down_by_draws(ctx, 1, walked);
    if (walked < n) walk_levels(ctx, walked);
    // Up from the level below the walked ones (which the walk finished), or from n-2.
    const std::size_t top = walked < n ? walked - 1 : n - 2;
    if (top >= 1) up_by_draws(ctx, top);
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
    first_downsample(ctx, source, ctx.settings.beam.bloom_threshold);
    if (n > 1) chain_past_level_zero(ctx);

    float total = 0.0f;
    for (std::size_t k = 0; k < n; ++k) total += mip_weight(w, k);
    t.bloom_out_fbo.bind();
    const gl::Program& last =
        last_step(ctx, ctx.programs.bloom_up, ctx.programs.bloom_up_glow, phosphor);
    last.set("u_final", 1);
    last.set("u_floor", ctx.settings.beam.bloom_floor);
    last.set("u_ratio", n > 1 ? mip_weight(w, 1) / mip_weight(w, 0) : 0.0f);
    last.set("u_weight", mip_weight(w, 0) / total);
    set_last_step_marks(ctx, last);
    t.bloom_mips[n > 1 ? 1 : 0].bind(kTextureUnitCoarser);
    t.bloom_mips[0].bind(kTextureUnitLevel);
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
    if (phosphor) {
        // Last frame's finished bloom becomes the glow history; this frame's is written over
        // the one before it.
        Targets& t = ctx.targets;
        std::swap(t.bloom_out, ctx.history.glow);
        std::swap(t.bloom_out_fbo, ctx.history.glow_fbo);
    }
    if (ctx.settings.beam.bloom == BloomKind::mip_chain && !ctx.targets.bloom_mips.empty()) {
        mip_chain_bloom(ctx, source, phosphor);
    } else {
        gaussian_bloom(ctx, source, phosphor);
    }
}

}  // namespace bz::render
