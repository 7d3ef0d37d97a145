#pragma once
// How long a frame of `play` should take at least, so the game never spins a core drawing
// what nobody needs: without vsync (llvmpipe, a driver that refuses it) the frame rate is
// capped at the display's refresh rate (or the player's max_fps); the menus over the attract
// demo draw at a lower rate, the pause menu (a still picture) lower still, and a minimised
// or hidden window only wakes to take events. Test runs (--frames) are never paced.
#include <cstdint>

namespace bz::app {

enum class PaceScene : std::uint8_t { play, title_menu, paused, hidden };

struct PaceInput {
    PaceScene scene = PaceScene::play;
    bool vsync_in_effect = false;  // what the driver gave, not what was asked for
    int max_fps = 0;               // the setting: 0 = the display's rate without vsync
    int display_hz = 0;            // 0: unknown (taken as 60)
    bool test_run = false;         // --frames: one tick per frame, as fast as it goes
};

inline constexpr int kTitleMenuFps = 30;  // the attract demo moves behind the title menu
inline constexpr int kPausedFps = 15;     // a still picture; keys still answer within a frame
inline constexpr int kHiddenFps = 10;     // nothing shown: only events and the audio run

// The least seconds a frame should take; 0 when pacing is left to vsync (or none applies).
double min_frame_seconds(const PaceInput& in);

}  // namespace bz::app
