#include "platform/synth.h"

#include <algorithm>
#include <cmath>

namespace bz::platform {

namespace {

constexpr float kTwoPi = 6.28318530718f;

float seconds_of(Sound s) {
    switch (s) {
        case Sound::shot:
            return 0.35f;
        case Sound::explosion:
            return 1.6f;
        case Sound::radar_blip:
            return 0.07f;
        case Sound::warning:
            return 0.5f;
    }
    return 0.1f;
}

float wrap(float phase) {
    return phase - std::floor(phase);
}
float square(float phase) {
    return phase < 0.5f ? 1.0f : -1.0f;
}
float saw(float phase) {
    return 2.0f * phase - 1.0f;
}

}  // namespace

float soft_clip(float x) {
    const float a = std::fabs(x);
    if (a <= 0.5f) return x;
    const float y = 0.5f + 0.5f * std::tanh((a - 0.5f) / 0.5f);
    return std::copysign(y, x);
}

Synth::Synth(int sample_rate, std::uint64_t seed)
    : rate_(std::max(1, sample_rate)), dt_(1.0f / static_cast<float>(rate_)), rng_(seed) {}

void Synth::set_volume(float v) {
    volume_ = std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f);
}

void Synth::set_engine(bool on, float speed) {
    engine_on_ = on;
    engine_target_ = std::clamp(std::isfinite(speed) ? speed : 0.0f, 0.0f, 1.0f);
}

std::size_t Synth::active_voices() const {
    return static_cast<std::size_t>(
        std::count_if(voices_.begin(), voices_.end(), [](const Voice& v) { return v.active; }));
}

void Synth::play(Sound s, float gain) {
    // A free voice, else steal the one nearest its end so the newest sound always plays.
    Voice* slot = &voices_[0];
    for (auto& v : voices_) {
        if (!v.active) {
            slot = &v;
            break;
        }
        if (v.length - v.t < slot->length - slot->t) slot = &v;
    }
    *slot = Voice{};
    slot->sound = s;
    slot->active = true;
    slot->length = static_cast<std::uint32_t>(seconds_of(s) * static_cast<float>(rate_));
    slot->gain = std::clamp(std::isfinite(gain) ? gain : 0.0f, 0.0f, 1.0f);
}

float Synth::voice_sample(Voice& v) {
    const float t = static_cast<float>(v.t) * dt_;
    const float len = static_cast<float>(v.length) * dt_;
    const float fade_in = std::min(1.0f, t * 400.0f);  // 2.5 ms: no click at the start
    float s = 0.0f;
    switch (v.sound) {
        case Sound::shot: {
            // A falling square sweep: the "pew" of a tank shell.
            const float f = 180.0f + 1100.0f * std::exp(-t * 12.0f);
            v.phase = wrap(v.phase + f * dt_);
            s = 0.45f * square(v.phase) * std::exp(-t * 9.0f);
            break;
        }
        case Sound::explosion: {
            // Noise through a low-pass that closes as the blast dies, over a low thump.
            const float k = 0.03f + 0.5f * std::exp(-t * 5.0f);
            v.low += k * (noise() - v.low);
            v.phase = wrap(v.phase + (55.0f - 20.0f * t / len) * dt_);
            const float thump = std::sin(kTwoPi * v.phase) * std::exp(-t * 6.0f);
            s = (1.4f * v.low + 0.5f * thump) * std::exp(-t * 2.6f);
            break;
        }
        case Sound::radar_blip: {
            v.phase = wrap(v.phase + 1320.0f * dt_);
            s = 0.35f * std::sin(kTwoPi * v.phase) * std::sin(3.14159265f * t / len);
            break;
        }
        case Sound::warning: {
            // Two tones alternating every eighth of a second.
            const float f = static_cast<int>(t * 8.0f) % 2 == 0 ? 880.0f : 660.0f;
            v.phase = wrap(v.phase + f * dt_);
            s = 0.25f * square(v.phase) * std::min(1.0f, (len - t) * 40.0f);
            break;
        }
    }
    if (++v.t >= v.length) v.active = false;
    return s * fade_in * v.gain;
}

float Synth::engine_sample() {
    // Glide speed and level at a rate that sounds like a motor, not a switch.
    engine_speed_ += (engine_target_ - engine_speed_) * std::min(1.0f, 4.0f * dt_);
    engine_level_ += ((engine_on_ ? 1.0f : 0.0f) - engine_level_) * std::min(1.0f, 8.0f * dt_);
    if (engine_level_ < 1e-4f && !engine_on_) return 0.0f;
    const float f = 32.0f + 68.0f * engine_speed_;
    engine_phase_ = wrap(engine_phase_ + f * dt_);
    engine_phase2_ = wrap(engine_phase2_ + 0.5f * f * dt_);
    engine_low_ += 0.08f * (noise() - engine_low_);
    const float tone = 0.6f * saw(engine_phase_) + 0.4f * std::sin(kTwoPi * engine_phase2_);
    return engine_level_ * (0.10f + 0.12f * engine_speed_) * (tone + 0.8f * engine_low_);
}

void Synth::render(float* out, std::size_t frames) {
    const float master = mute_ ? 0.0f : volume_;
    for (std::size_t i = 0; i < frames; ++i) {
        float mix = engine_sample();
        for (auto& v : voices_) {
            if (v.active) mix += voice_sample(v);
        }
        out[i] = mute_ ? 0.0f : soft_clip(mix * master);
    }
}

}  // namespace bz::platform
