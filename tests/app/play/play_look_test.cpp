// play's look: which of the command line, the level's [render] section and the settings file
// decides the style and the preset, with the level's overrides on top.
#include "app/play/play_look.h"

#include <gtest/gtest.h>

#include "level/loader.h"
#include "platform/settings.h"
#include "scene/style_table.h"

namespace bz::app {
namespace {

level::Level load(const char* text) {
    level::LoadResult r = level::load_level_string(text, "look.toml");
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : level::format(r.errors.front()));
    return r.ok() ? *r.level : level::Level{};
}

// What the settings file says, as cmd_play reads it.
LookSources from_settings(const char* text) {
    const platform::SettingsLoad s = platform::parse_settings(
        text, "settings.toml", {render::preset_names(), scene::accepted_style_name_strings()});
    EXPECT_TRUE(s.errors.empty());
    LookSources out;
    out.settings_style = s.settings.style;
    out.settings_style_given = s.style_given;
    if (s.preset_given) out.settings_preset = s.settings.preset;
    if (s.beam_given) out.settings_beam = s.settings.beam;
    out.settings_overlay = s.settings.overlay;
    out.settings_hold_41hz = s.settings.hold_41hz;
    return out;
}

constexpr const char* kStyled =
    "version = 1\nname = \"L\"\n[render]\nstyle = \"arcade\"\npreset = \"high\"\nline_width = 3\n"
    "crease_angle = 45\nbloom_strength = 0.5\n";
constexpr const char* kPlain = "version = 1\nname = \"L\"\n";

TEST(PlayLook, LevelStyleBeatsTheSettingsFileButNotTheCommandLine) {
    const level::Level lv = load(kStyled);
    ASSERT_TRUE(lv.render.style_given);
    LookSources s = from_settings("style = \"occluded\"\npreset = \"fast\"\n");
    PlayLook look = choose_look(s, &lv);
    EXPECT_EQ(look.style, scene::LineStyle::arcade);
    EXPECT_EQ(look.render.preset, "fast") << "the player's machine decides the speed";
    EXPECT_EQ(
        look.summary,
        "style vector-xray (level), preset fast (settings file), beam mame (default), line width "
        "3 px (level), "
        "crease angle 45 deg (level), bloom strength 0.5 (level)");

    s.cli_style = "occluded";
    s.cli_preset = "balanced";
    look = choose_look(s, &lv);
    EXPECT_EQ(look.style, scene::LineStyle::occluded);
    EXPECT_EQ(look.render.preset, "balanced");
    EXPECT_EQ(look.summary.substr(0, 50), "style vector (command line), preset balanced (comm");
}

TEST(PlayLook, LevelOverridesApplyOnTopOfAnyPreset) {
    const level::Level lv = load(kStyled);
    for (const std::string& p : render::preset_names()) {
        LookSources s;
        s.cli_preset = p;
        const PlayLook look = choose_look(s, &lv);
        const render::RenderSettings base = render::preset(p);
        EXPECT_EQ(look.render.preset, p);
        EXPECT_FLOAT_EQ(look.render.line_half_width_px, 1.5f);
        EXPECT_FLOAT_EQ(look.render.crease_angle_deg, 45.0f);
        EXPECT_FLOAT_EQ(look.render.bloom_strength, 0.5f);
        EXPECT_EQ(look.render.bloom_taps, base.bloom_taps) << "the rest is the preset's";
    }
}

TEST(PlayLook, LevelPresetFillsInOnlyWhereTheSettingsNameNone) {
    const level::Level lv = load("version = 1\nname = \"L\"\n[render]\npreset = \"fast\"\n");
    EXPECT_FALSE(lv.render.style_given);
    EXPECT_TRUE(lv.render.preset_given);

    PlayLook look = choose_look(from_settings("style = \"arcade\"\n"), &lv);
    EXPECT_EQ(look.render.preset, "fast");
    EXPECT_EQ(look.style, scene::LineStyle::arcade) << "the level names no style";
    EXPECT_EQ(look.summary,
              "style vector-xray (settings file), preset fast (level), beam mame (default)");

    look = choose_look(from_settings("preset = \"high\"\n"), &lv);
    EXPECT_EQ(look.render.preset, "high");
    EXPECT_EQ(look.style, scene::LineStyle::occluded);
    EXPECT_EQ(look.summary,
              "style vector (default), preset high (settings file), beam mame (default)");
}

TEST(PlayLook, DefaultsWithNoLevelAndNoChoices) {
    const level::Level plain = load(kPlain);
    EXPECT_FALSE(plain.render.style_given);
    EXPECT_FALSE(plain.render.preset_given);
    for (const level::Level* lv : {&plain, static_cast<const level::Level*>(nullptr)}) {
        const PlayLook look = choose_look(LookSources{}, lv);
        EXPECT_EQ(look.style, scene::LineStyle::occluded);
        EXPECT_EQ(look.render.preset, "balanced");
        EXPECT_EQ(look.summary,
                  "style vector (default), preset balanced (default), beam mame (default)");
    }
}

TEST(PlayLook, BeamIsMameByDefaultAndFollowsCommandLineThenSettingsThenLevel) {
    const level::Level lv =
        load("version = 1\nname = \"L\"\n[render]\nbeam = \"classic\"\noverlay = true\n");
    ASSERT_EQ(lv.render.beam, std::optional<std::string>("classic"));
    PlayLook look = choose_look(LookSources{}, nullptr);
    EXPECT_EQ(look.render.beam.look, "mame");
    EXPECT_EQ(look.render.beam.blend, render::BeamBlend::additive);
    EXPECT_FALSE(look.render.beam.overlay);
    EXPECT_EQ(look.render.beam.refresh_hz, 0.0f);

    look = choose_look(LookSources{}, &lv);  // the level's beam and overlay
    EXPECT_EQ(look.render.beam.look, "classic");
    EXPECT_TRUE(look.render.beam.overlay);

    LookSources s = from_settings("beam = \"mame\"\nhold_41hz = true\n");
    look = choose_look(s, &lv);  // the settings file names a beam: it wins over the level's
    EXPECT_EQ(look.render.beam.look, "mame");
    EXPECT_TRUE(look.render.beam.overlay) << "the level's overlay still applies";
    EXPECT_FLOAT_EQ(look.render.beam.refresh_hz, 41.0f);
    EXPECT_NE(look.summary.find("beam mame (settings file), overlay, 41 Hz hold"),
              std::string::npos)
        << look.summary;

    s.cli_beam = "classic";
    EXPECT_EQ(choose_look(s, &lv).render.beam.look, "classic");
}

TEST(PlayLook, FlashesSoftenOrStopFlickerAndTrailsAndColourSafeReachesTheOverlay) {
    LookSources s;
    const PlayLook full = choose_look(s, nullptr);
    ASSERT_GT(full.render.beam.flicker, 0.0f) << "the mame beam flickers";
    ASSERT_NE(full.render.beam.phosphor, render::PhosphorDecay::off);
    s.flashes = "soft";
    const PlayLook soft = choose_look(s, nullptr);
    EXPECT_FLOAT_EQ(soft.render.beam.flicker, 0.5f * full.render.beam.flicker);
    EXPECT_FLOAT_EQ(soft.render.beam.persistence_ms, 0.5f * full.render.beam.persistence_ms);
    s.flashes = "off";
    s.colour_safe = true;
    const PlayLook off = choose_look(s, nullptr);
    EXPECT_EQ(off.render.beam.flicker, 0.0f);
    EXPECT_EQ(off.render.beam.phosphor, render::PhosphorDecay::off);
    EXPECT_TRUE(off.render.beam.colour_safe);
    EXPECT_NE(off.summary.find("no flicker or trails"), std::string::npos) << off.summary;
}

TEST(PlayLook, ABadSettingsValueDoesNotCountAsNamed) {
    const platform::SettingsLoad s =
        platform::parse_settings("preset = \"ultra\"\nstyle = 3\n", "settings.toml",
                                 {render::preset_names(), scene::accepted_style_name_strings()});
    EXPECT_EQ(s.errors.size(), 2u);
    EXPECT_FALSE(s.preset_given);
    EXPECT_FALSE(s.style_given);
}

}  // namespace
}  // namespace bz::app

namespace bz::app {
namespace {

// The settings file (platform, which may not link scene) keeps its own copy of the style
// names: every name the scene accepts must load from it, and choose the same style.
TEST(PlayLook, EveryStyleNameWorksInTheSettingsFileAndTheLevel) {
    for (const std::string_view name : scene::accepted_style_names()) {
        SCOPED_TRACE(std::string(name));
        const std::string settings = "style = \"" + std::string(name) + "\"\n";
        const LookSources s = from_settings(settings.c_str());
        EXPECT_TRUE(s.settings_style_given);
        EXPECT_EQ(choose_look(s, nullptr).style, scene::style_from_name(name));
        const std::string level_text =
            "version = 1\nname = \"L\"\n[render]\nstyle = \"" + std::string(name) + "\"\n";
        const level::Level lv = load(level_text.c_str());
        EXPECT_EQ(choose_look(LookSources{}, &lv).style, scene::style_from_name(name));
    }
}

}  // namespace
}  // namespace bz::app
