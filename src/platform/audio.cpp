#include "platform/audio.h"

#include <SDL.h>

#include <algorithm>
#include <optional>
#include <string>

#include "core/log.h"
#include "core/stderr_capture.h"

namespace bz::platform {

namespace {

void fill(void* user, Uint8* stream, int bytes) {
    auto* synth = static_cast<Synth*>(user);
    synth->render(reinterpret_cast<float*>(stream),
                  static_cast<std::size_t>(bytes) / sizeof(float));
}

}  // namespace

namespace {

// What the sound libraries under SDL print straight to stderr while a device is looked for
// (ALSA's "ALSA lib ...: Unknown PCM default" lines on a machine without a sound card) goes
// to the log, not the terminal: the game's own one-line warning says what it means.
void log_library_output(Log& log, StderrCapture& captured) {
    const std::string text = captured.text();
    if (!text.empty()) log.write(LogLevel::debug, "audio libraries said: " + text);
}

}  // namespace

Audio::Audio(Log& log, float volume, bool mute) : volume_(volume), mute_(mute) {
    std::optional<StderrCapture> quiet(std::in_place);
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
        log_library_output(log, *quiet);
        log.warn(std::string("no audio (") + SDL_GetError() + "); playing silently");
        return;
    }
    started_ = true;
    SDL_AudioSpec want{};
    want.freq = 48000;
    want.format = AUDIO_F32SYS;
    want.channels = 1;
    want.samples = 1024;  // ~21 ms: small enough that a shot sounds with its flash
    want.callback = fill;
    SDL_AudioSpec have{};
    // Only the rate may change; SDL converts format and channels for us.
    synth_ = std::make_unique<Synth>(want.freq);
    want.userdata = synth_.get();
    device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, SDL_AUDIO_ALLOW_FREQUENCY_CHANGE);
    log_library_output(log, *quiet);
    quiet.reset();
    if (device_ == 0) {
        log.warn(std::string("cannot open an audio device (") + SDL_GetError() +
                 "); playing silently");
        synth_.reset();
        return;
    }
    if (have.freq != want.freq) *synth_ = Synth(have.freq);  // the callback has not run yet
    synth_->set_volume(volume);
    synth_->set_mute(mute);
    SDL_PauseAudioDevice(device_, 0);
    log.info("audio: " + std::string(SDL_GetCurrentAudioDriver()) + ", " +
             std::to_string(have.freq) + " Hz");
}

Audio::~Audio() {
    if (device_ != 0) SDL_CloseAudioDevice(device_);
    if (started_) SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

template <class F>
void Audio::with_synth(F&& f) {
    if (device_ == 0) return;
    SDL_LockAudioDevice(device_);
    f(*synth_);
    SDL_UnlockAudioDevice(device_);
}

void Audio::play(Sound s, float gain) {
    with_synth([&](Synth& synth) { synth.play(s, gain); });
}

void Audio::set_engine(bool on, float speed) {
    with_synth([&](Synth& synth) { synth.set_engine(on, speed); });
}

void Audio::set_volume(float v) {
    volume_ = std::clamp(v, 0.0f, 1.0f);
    with_synth([&](Synth& synth) { synth.set_volume(volume_); });
}

void Audio::set_mute(bool m) {
    mute_ = m;
    with_synth([&](Synth& synth) { synth.set_mute(m); });
}

}  // namespace bz::platform
