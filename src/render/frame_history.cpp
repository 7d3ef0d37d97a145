#include "render/frame_history.h"

#include "render/targets.h"

namespace bz::render {

namespace {

// The phosphor's images are allocated together, for any of them.
bool names_phosphor_images(ResourceSet set) {
    return set.has(Resource::phosphor) || set.has(Resource::picture_lit) || set.has(Resource::glow);
}

}  // namespace

bool FrameHistory::has_images_for(ResourceSet needed) const {
    return !names_phosphor_images(needed) || static_cast<bool>(phosphor);
}

bool FrameHistory::has_images_beyond(ResourceSet needed) const {
    return static_cast<bool>(phosphor) && !names_phosphor_images(needed);
}

FrameHistory FrameHistory::make(int width, int height, int bloom_w, int bloom_h, ResourceSet needed,
                                HistoryCut why) {
    FrameHistory h;
    h.last_cut_ = why;
    if (!names_phosphor_images(needed)) return h;
    const int lit_x = (width + kLitTileSize - 1) / kLitTileSize;
    const int lit_y = (height + kLitTileSize - 1) / kLitTileSize;
    h.phosphor = gl::Texture2D(width, height, GL_RGBA16F, gl::Filter::linear);
    glClearTexImage(h.phosphor.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    h.picture_lit = gl::Texture2D(lit_x, lit_y, GL_R8UI, gl::Filter::nearest);
    glClearTexImage(h.picture_lit.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    h.glow = gl::Texture2D(bloom_w, bloom_h, GL_RGBA8, gl::Filter::linear);
    glClearTexImage(h.glow.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    h.glow_fbo = gl::Framebuffer({&h.glow}, nullptr);
    return h;
}

void FrameHistory::forget(HistoryCut why) {
    if (blank_ && held_.empty() && frame_writes_.empty()) return;  // nothing to forget
    last_cut_ = why;
    held_ = {};
    frame_writes_ = {};
    picture_ = nullptr;
    if (blank_) return;  // nothing drew into its images since they were last cleared
    blank_ = true;
    if (phosphor) glClearTexImage(phosphor.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
    if (picture_lit)
        glClearTexImage(picture_lit.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
}

void FrameHistory::keep(ResourceSet frame_writes, const gl::Texture2D* picture, double time_s) {
    held_ = {};
    frame_writes_ = frame_writes;
    for (int i = 0; i < kResourceCount; ++i) {
        const auto r = static_cast<Resource>(i);
        if (is_history(r) && frame_writes.has(r)) held_.add(r);
    }
    if (held_.has(Resource::phosphor)) blank_ = false;
    picture_ = held_.has(Resource::picture) ? picture : nullptr;
    time_s_ = time_s;
}

}  // namespace bz::render
