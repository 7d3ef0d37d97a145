#pragma once
// The one clock the look runs on. Phosphor decay, the held 41 Hz refresh and the beam's
// flicker follow the time at which frames are presented, not the simulation: a paused game,
// a menu or the --edit viewer has no simulation time, yet its pictures must still fade.
//
// Who advances it, and by what:
//   play, pause, menus, --edit, a replay watched in the window: the play loop, by the real
//     time between drawn frames (or one 60 Hz tick per frame under --frames, so a scripted
//     run does the same work on any machine);
//   bench, render --repeat, headless replays: one nominal 60 Hz frame per picture
//     (advance_nominal), so the same run draws the same pictures on any machine.
// The world stamps its frames with simulation ticks (World::interpolated_frame), which is what
// a fixed-rate run presents anyway; whoever presents a frame stamps it with this clock just
// before it is drawn, so interactive runs follow the screen, not the simulation.
#include <algorithm>
#include <cstdint>

#include "scene/frame_list.h"

namespace bz::scene {

class PresentationClock {
  public:
    static constexpr double kNominalHz = 60.0;

    // The next frame is presented `dt_seconds` after the last one (negative counts as 0).
    void advance(double dt_seconds) {
        time_s_ += std::max(dt_seconds, 0.0);
        ++frame_;
    }
    void advance_nominal() { advance(1.0 / kNominalHz); }

    // Puts this clock's time and flicker seed on a frame about to be drawn.
    void stamp(FrameList& frame) const {
        frame.time_s = time_s_;
        frame.seed = frame_;
    }

    double time_s() const { return time_s_; }
    std::uint32_t frame() const { return frame_; }

  private:
    double time_s_ = 0.0;
    std::uint32_t frame_ = 0;
};

}  // namespace bz::scene
