#pragma once
// Sound effects made from oscillators and noise at run time (no sound files), in a form that
// runs without an audio device: render() fills a buffer, and tests can inspect it.
#include <array>
#include <cstddef>
#include <cstdint>

#include "core/rng.h"

namespace bz::platform {

enum class Sound : std::uint8_t { shot, explosion, radar_blip, warning };

class Synth {
  public:
    explicit Synth(int sample_rate, std::uint64_t seed = 1);

    void play(Sound s, float gain = 1.0f);
    // The engine rumble runs continuously while on; its pitch and loudness follow `speed`
    // (0 idle .. 1 full), glided so changes never click.
    void set_engine(bool on, float speed);
    void set_volume(float v);  // 0..1, clamped
    void set_mute(bool m) { mute_ = m; }
    float volume() const { return volume_; }
    bool muted() const { return mute_; }
    int sample_rate() const { return rate_; }
    std::size_t active_voices() const;

    // Mono samples in -1..1. Muted output is exact zeros (time still passes for the voices).
    void render(float* out, std::size_t frames);

  private:
    struct Voice {
        Sound sound = Sound::shot;
        bool active = false;
        std::uint32_t t = 0;       // samples since start
        std::uint32_t length = 0;  // samples
        float gain = 1.0f;
        float phase = 0.0f;  // 0..1
        float low = 0.0f;    // one-pole low-pass state for noise
    };
    float voice_sample(Voice& v);
    float engine_sample();
    float noise() { return static_cast<float>(rng_.uniform(-1.0, 1.0)); }

    int rate_;
    float dt_;
    Rng rng_;
    std::array<Voice, 16> voices_{};
    bool engine_on_ = false;
    float engine_target_ = 0.0f;
    float engine_speed_ = 0.0f;
    float engine_level_ = 0.0f;  // fades in and out with on/off
    float engine_phase_ = 0.0f;
    float engine_phase2_ = 0.0f;
    float engine_low_ = 0.0f;
    float volume_ = 0.8f;
    bool mute_ = false;
};

// Bounded soft clip: identity below 0.5, approaches +-1 smoothly above.
float soft_clip(float x);

}  // namespace bz::platform
