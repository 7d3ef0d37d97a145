#include "render/passes.h"

namespace bz::render {

void draw_tile_quads(const gl::Program& program, const gl::Texture2D& tiles, glm::ivec2 screen) {
    program.set("u_screen", screen);
    tiles.bind(kTextureUnitTiles);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, tiles.width() * tiles.height());
}

void bind_lit_tile_marks(const gl::Program& program, const Targets& targets, bool mark) {
    program.set("u_mark_tiles", mark ? 1 : 0);
    if (mark) {
        glBindImageTexture(kImageUnitLitTiles, targets.lit_tiles.id(), 0, GL_FALSE, 0,
                           GL_WRITE_ONLY, GL_R8UI);
    }
}

// The list of tiles the sparse composite shades (shaders/beam/tile_list.comp).
// Reads: Targets::lit_tiles (marked this frame by the bloom's first downsample and last step),
// with the phosphor FrameHistory::picture_lit (marked by last frame's composite).
// Writes: Targets::tile_list, the indirect draw command and the runs of lit tiles after it
// (one quad each for the composite: on llvmpipe a 16x16 quad cost about as much to set up as
// to shade, see docs/measurements/lit-tiles.md).
// One invocation per row reading one mark or two per tile: it reads no image's texels, so it
// costs the same on any frame, 45 invocations at 1280x720.
void pass_tiles(const PassContext& ctx) {
    Targets& t = ctx.targets;
    if (!t.lit_tiles) return;
    const PhosphorStep* phosphor =
        ctx.picture && ctx.picture->phosphor ? &*ctx.picture->phosphor : nullptr;
    // The lit-tile marks were written by fragment stages as images.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    const GLuint command[4] = {6, 0, 0, 0};  // 6 vertices per tile, no tile yet
    glNamedBufferSubData(t.tile_list.id(), 0, sizeof(command), command);
    const GLuint none = 0;
    glNamedBufferSubData(t.lit_tile_count.id(), 0, sizeof(none), &none);
    const gl::Program& p = ctx.programs.tile_list;
    p.use();
    p.set("u_phosphor", phosphor ? 1 : 0);
    t.lit_tiles.bind(kTextureUnitMarks);
    if (phosphor) ctx.history.picture_lit.bind(kTextureUnitPictureLit);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBinding, t.tile_list.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLitTileCountBinding, t.lit_tile_count.id());
    const GLuint rows = static_cast<GLuint>(t.lit_tiles.height());  // one invocation per row
    glDispatchCompute((rows + 63) / 64, 1, 1);
    // The composite reads the list as its draw command and in its vertex stage.
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void draw_listed_tiles(const gl::Program& program, const Targets& targets, glm::ivec2 screen) {
    program.set("u_screen", screen);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBinding, targets.tile_list.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, targets.tile_list.id());
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace bz::render
