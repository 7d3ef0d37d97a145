#include "app/play/frame_pacer.h"

#include <algorithm>

namespace bz::app {

namespace {

constexpr int kFallbackHz = 60;

}  // namespace

double min_frame_seconds(const PaceInput& in) {
    if (in.test_run) return 0.0;
    const int display = in.display_hz > 0 ? in.display_hz : kFallbackHz;
    // The game's own cap: the player's, else the display's rate when vsync does not pace us.
    int cap = in.max_fps > 0 ? in.max_fps : (in.vsync_in_effect ? 0 : display);
    switch (in.scene) {
        case PaceScene::play:
            break;
        case PaceScene::title_menu:
            cap = cap > 0 ? std::min(cap, kTitleMenuFps) : kTitleMenuFps;
            break;
        case PaceScene::paused:
            cap = cap > 0 ? std::min(cap, kPausedFps) : kPausedFps;
            break;
        case PaceScene::hidden:
            cap = kHiddenFps;
            break;
    }
    return cap > 0 ? 1.0 / cap : 0.0;
}

}  // namespace bz::app
