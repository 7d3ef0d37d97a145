// Opening audio must never be fatal: with SDL's dummy driver, or with no usable driver at all,
// the game carries on (silently in the second case).
#include <SDL.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/log.h"
#include "platform/audio.h"

namespace bz::platform {
namespace {

TEST(AudioDevice, DummyDriverWorksAndCallsAreSafe) {
    ::setenv("SDL_AUDIODRIVER", "dummy", 1);
    Log log;
    Audio audio(log, 0.5f, false);
    audio.play(Sound::explosion);
    audio.set_engine(true, 0.7f);
    audio.set_volume(2.0f);
    EXPECT_EQ(audio.volume(), 1.0f);
    audio.set_mute(true);
    EXPECT_TRUE(audio.muted());
    SDL_Delay(30);  // let the callback run a few times
}

TEST(AudioDevice, NoDriverMeansSilentNotFatal) {
    ::setenv("SDL_AUDIODRIVER", "no-such-driver", 1);
    Log log;
    Audio audio(log, 0.5f, false);
    EXPECT_FALSE(audio.active());
    audio.play(Sound::shot);  // no-ops
    audio.set_engine(true, 1.0f);
    audio.set_volume(0.1f);
    EXPECT_FLOAT_EQ(audio.volume(), 0.1f);
    ::setenv("SDL_AUDIODRIVER", "dummy", 1);
}

}  // namespace
}  // namespace bz::platform
