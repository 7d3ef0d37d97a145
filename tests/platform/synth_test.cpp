#include "platform/synth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bz::platform {
namespace {

constexpr int kRate = 48000;

struct Levels {
    float peak = 0.0f;
    double rms = 0.0;
};

Levels levels(const std::vector<float>& s) {
    Levels l;
    double sum = 0.0;
    for (const float x : s) {
        l.peak = std::max(l.peak, std::fabs(x));
        sum += static_cast<double>(x) * x;
    }
    l.rms = std::sqrt(sum / static_cast<double>(s.size()));
    return l;
}

std::vector<float> render(Synth& synth, double seconds) {
    std::vector<float> out(static_cast<std::size_t>(seconds * kRate));
    synth.render(out.data(), out.size());
    return out;
}

// Zero crossings per second / 2 after a 5 ms moving average (which removes the rumble's
// noise but keeps its < 120 Hz tone): a rough pitch estimate.
double crossings_hz(const std::vector<float>& raw) {
    const std::size_t w = kRate / 200;
    std::vector<float> s;
    double sum = 0.0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        sum += raw[i];
        if (i >= w) sum -= raw[i - w];
        if (i + 1 >= w) s.push_back(static_cast<float>(sum / w));
    }
    int n = 0;
    for (std::size_t i = 1; i < s.size(); ++i) n += (s[i - 1] < 0.0f) != (s[i] < 0.0f);
    return n / 2.0 / (static_cast<double>(s.size()) / kRate);
}

TEST(Synth, SilentUntilSomethingPlays) {
    Synth synth(kRate);
    EXPECT_EQ(levels(render(synth, 0.1)).peak, 0.0f);
}

TEST(Synth, EverySoundIsAudibleAndBounded) {
    for (const Sound s : {Sound::shot, Sound::explosion, Sound::radar_blip, Sound::warning}) {
        Synth synth(kRate);
        synth.set_volume(1.0f);
        synth.play(s);
        const Levels l = levels(render(synth, 0.05));
        EXPECT_GT(l.rms, 0.01) << static_cast<int>(s);
        EXPECT_LE(l.peak, 1.0f) << static_cast<int>(s);
    }
}

TEST(Synth, SoundsEnd) {
    Synth synth(kRate);
    synth.play(Sound::shot);
    synth.play(Sound::radar_blip);
    synth.play(Sound::explosion);
    synth.play(Sound::warning);
    EXPECT_EQ(synth.active_voices(), 4u);
    render(synth, 2.0);
    EXPECT_EQ(synth.active_voices(), 0u);
    EXPECT_EQ(levels(render(synth, 0.1)).peak, 0.0f);
}

TEST(Synth, ManyOverlappingSoundsStayBounded) {
    Synth synth(kRate);
    synth.set_volume(1.0f);
    synth.set_engine(true, 1.0f);
    for (int i = 0; i < 40; ++i) synth.play(i % 2 ? Sound::explosion : Sound::shot);
    EXPECT_LE(synth.active_voices(), 16u);
    const Levels l = levels(render(synth, 0.5));
    EXPECT_LE(l.peak, 1.0f);
    EXPECT_GT(l.peak, 0.5f);
}

TEST(Synth, MuteIsExactSilenceAndVolumeScales) {
    Synth loud(kRate), quiet(kRate), muted(kRate);
    loud.set_volume(0.8f);
    quiet.set_volume(0.2f);
    muted.set_volume(1.0f);
    muted.set_mute(true);
    for (Synth* s : {&loud, &quiet, &muted}) {
        s->set_engine(true, 0.5f);
        s->play(Sound::radar_blip);
    }
    const auto a = render(loud, 0.05), b = render(quiet, 0.05), c = render(muted, 0.05);
    for (const float x : c) ASSERT_EQ(x, 0.0f);
    // Quiet signals stay in the linear part of the clipper: exactly a quarter.
    EXPECT_NEAR(levels(b).rms * 4.0, levels(a).rms, 1e-4);
}

TEST(Synth, EnginePitchFollowsSpeed) {
    Synth idle(kRate), fast(kRate);
    idle.set_engine(true, 0.0f);
    fast.set_engine(true, 1.0f);
    render(idle, 1.5);  // let the glide settle
    render(fast, 1.5);
    const auto a = render(idle, 1.0), b = render(fast, 1.0);
    EXPECT_GT(levels(a).rms, 0.01);
    EXPECT_GT(crossings_hz(b), crossings_hz(a) * 1.5);
    Synth off(kRate);
    off.set_engine(false, 1.0f);
    EXPECT_EQ(levels(render(off, 0.1)).peak, 0.0f);
}

TEST(Synth, SoftClipIsBoundedAndMonotonic) {
    float prev = -2.0f;
    for (float x = -100.0f; x <= 100.0f; x += 0.01f) {
        const float y = soft_clip(x);
        EXPECT_LE(std::fabs(y), 1.0f);
        EXPECT_GE(y, prev);
        prev = y;
    }
    EXPECT_EQ(soft_clip(0.3f), 0.3f);
}

TEST(Synth, NonFiniteInputsAreTamed) {
    Synth synth(kRate);
    synth.set_volume(std::nanf(""));
    synth.set_engine(true, INFINITY);
    synth.play(Sound::shot, std::nanf(""));
    for (const float x : render(synth, 0.1)) ASSERT_TRUE(std::isfinite(x));
}

}  // namespace
}  // namespace bz::platform
