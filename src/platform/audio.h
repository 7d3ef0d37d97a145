#pragma once
// The audio device: a Synth behind SDL's audio callback. Having no audio (no device, the
// dummy driver, a failed open) is normal: it logs one line and every call becomes a no-op.
#include <memory>

#include "platform/synth.h"

namespace bz {
class Log;
}

namespace bz::platform {

class Audio {
  public:
    Audio(Log& log, float volume, bool mute);
    ~Audio();
    Audio(const Audio&) = delete;
    Audio& operator=(const Audio&) = delete;

    bool active() const { return device_ != 0; }
    void play(Sound s, float gain = 1.0f);
    void set_engine(bool on, float speed);
    void set_volume(float v);
    void set_mute(bool m);
    float volume() const { return volume_; }
    bool muted() const { return mute_; }

  private:
    template <class F>
    void with_synth(F&& f);

    std::unique_ptr<Synth> synth_;
    unsigned device_ = 0;  // SDL_AudioDeviceID; 0 = silent
    bool started_ = false;
    float volume_;
    bool mute_;
};

}  // namespace bz::platform
