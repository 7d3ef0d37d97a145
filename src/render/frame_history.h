#pragma once
// What one view keeps from frame to frame: the phosphor picture and its lit tiles, the glow
// (last frame's finished bloom, decayed with the phosphor) and the last beam picture with the
// time it was shown (which a held frame shows again, and from which the phosphor decays).
// Every other target lives and dies within its frame (targets.h).
//
// The rules: the history holds what the last drawn frame's passes wrote of it (their declared
// writes, frame_passes.h), and nothing after any of
//   - resize: new targets, so the picture has another size;
//   - style change: a frame of another style than the last (its picture is not this one's
//     past; a filled style writes no beam picture at all);
//   - settings change that remakes the targets (bloom size, phosphor on/off, depth, method);
//   - cut: FrameList::cut, the camera jumps or the level is (re)loaded;
//   - a frame drawn with RenderSettings::keep_history off (--edit: its camera flies freely).
// The phosphor's and picture_lit's texels are read as images by every phosphor frame, so
// forgetting them clears them (once: a blank history is not cleared again).
#include "gl/framebuffer.h"
#include "render/frame_resources.h"
#include "render/settings.h"

namespace bz::render {

// Why a view's history was last forgotten: the rules above, and no_past for a frame drawn
// after one that left no beam picture (a filled style's).
enum class HistoryCut { resize, style_change, settings_change, camera_cut, no_history, no_past };

class FrameHistory {
  public:
    // The phosphor's images and the glow's second bloom image, when `needed` (a frame's pass
    // list, frame_passes.h) names any of them, at `width` x `height` and the bloom resolution
    // `bloom_w` x `bloom_h`. Everything starts black, with no tile lit; it holds nothing, as
    // forgotten for `why`.
    static FrameHistory make(int width, int height, int bloom_w, int bloom_h, ResourceSet needed,
                             HistoryCut why);
    // Whether it has the images of every history resource `needed` names.
    bool has_images_for(ResourceSet needed) const;
    // Whether it has images that no resource of `needed` names.
    bool has_images_beyond(ResourceSet needed) const;

    // What the history holds now: history resources (frame_resources.h) a frame wrote and no
    // cut has forgotten since.
    bool holds(Resource r) const { return held_.has(r); }
    ResourceSet held() const { return held_; }
    // Everything the last frame drawn wrote (a held frame shows it again, reading its bloom
    // and its list of lit tiles); nothing after a cut.
    ResourceSet frame_writes() const { return frame_writes_; }
    // Forgets everything (the rules above).
    void forget(HistoryCut why);
    // The reason of the last forget() that forgot something (tests read it).
    HistoryCut last_cut() const { return last_cut_; }
    // After a frame: it holds what that frame's passes wrote of it, `picture` (the lines
    // target or the phosphor picture; null for a frame without a beam picture) shown at
    // `time_s`.
    void keep(ResourceSet frame_writes, const gl::Texture2D* picture, double time_s);

    // The last beam picture and when it was shown; null when the history holds none.
    const gl::Texture2D* picture() const { return holds(Resource::picture) ? picture_ : nullptr; }
    double time_s() const { return time_s_; }

    // The phosphor picture (RGBA16F, alpha = age for the power law), updated in place by the
    // composite, which loads each pixel's own texel and stores the new value only where it
    // changed.
    gl::Texture2D phosphor;
    // Which lit tiles of the picture hold light (R8UI, like Targets::lit_tiles): read by
    // tile_list.comp (those must be decayed this frame), then cleared and marked again by the
    // composite.
    gl::Texture2D picture_lit;
    // Last frame's finished bloom (like Targets::bloom_out, which it swaps with each phosphor
    // frame): the glow persists with the phosphor (shaders/beam/glow_persistence.glsl).
    gl::Texture2D glow;
    gl::Framebuffer glow_fbo;

  private:
    ResourceSet held_;
    ResourceSet frame_writes_;
    const gl::Texture2D* picture_ = nullptr;
    double time_s_ = 0.0;
    HistoryCut last_cut_ = HistoryCut::resize;
    // The phosphor images hold nothing (cleared, or new): forget() need not clear them again.
    bool blank_ = true;
};

}  // namespace bz::render
