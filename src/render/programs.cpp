#include "render/programs.h"

#include "core/paths.h"

namespace bz::render {

Programs load_programs() {
    const auto dir = shaders_dir();
    auto stage = [&](GLenum type, const char* file) { return gl::StageFile{type, dir / file}; };
    Programs p;
    p.prepass = gl::Program({stage(GL_VERTEX_SHADER, "prepass.vert")});
    p.lines = gl::Program({stage(GL_VERTEX_SHADER, "lines.vert"), stage(GL_GEOMETRY_SHADER, "lines.geom"),
                           stage(GL_FRAGMENT_SHADER, "lines.frag")});
    p.mask = gl::Program({stage(GL_VERTEX_SHADER, "lines.vert"), stage(GL_GEOMETRY_SHADER, "lines.geom"),
                          stage(GL_FRAGMENT_SHADER, "lines.frag")},
                         {"MASK_MODE 1"});
    p.hud = gl::Program({stage(GL_VERTEX_SHADER, "hud.vert"), stage(GL_GEOMETRY_SHADER, "hud.geom"),
                         stage(GL_FRAGMENT_SHADER, "hud.frag")});
    p.bloom_down = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                stage(GL_FRAGMENT_SHADER, "bloom_down.frag")});
    p.bloom_blur = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                stage(GL_FRAGMENT_SHADER, "bloom_blur.frag")});
    p.composite = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                               stage(GL_FRAGMENT_SHADER, "composite.frag")});
    return p;
}

}  // namespace bz::render
