#include "app/play/menu/play_menus.h"

#include <SDL_scancode.h>
#include <gtest/gtest.h>

namespace bz::app::menu {
namespace {

using platform::MenuKey;
using Kind = Request::Kind;

struct Fixture {
    platform::Settings settings;
    game::HighScoreTable scores = game::HighScoreTable::defaults();
    PlayMenus menus;
    Fixture() : menus(make_env()) {}
    Env make_env() {
        Env e;
        e.settings = &settings;
        e.presets = {"fast", "balanced", "high"};
        e.levels = {{"CLASSIC", "/l/classic.toml"},
                    {"MAZE", "/l/maze.toml"},
                    {"MINE", "/u/mine.toml", true}};
        e.current_level = "/l/classic.toml";
        e.high_scores = &scores;
        return e;
    }
    std::vector<Request> keys(std::initializer_list<MenuKey> ks) {
        std::vector<Request> out;
        for (const MenuKey k : ks) {
            for (const Request& r : menus.handle(k)) out.push_back(r);
        }
        return out;
    }
};

std::vector<std::string> labels(const Page& p) {
    std::vector<std::string> out;
    for (const Row& r : p.rows) out.push_back(r.label);
    return out;
}

TEST(PlayMenus, TitleMenuHasTheIssuesItemsAndStarts) {
    Fixture f;
    EXPECT_FALSE(f.menus.open());
    f.menus.set_context(Context::title);
    ASSERT_TRUE(f.menus.open());
    EXPECT_EQ(
        labels(f.menus.page()),
        (std::vector<std::string>{"START", "LEVEL", "OPTIONS", "CONTROLS", "HIGH SCORES", "QUIT"}));
    EXPECT_EQ(f.menus.page().rows[1].value, "CLASSIC");
    EXPECT_EQ(f.keys({MenuKey::confirm}), std::vector<Request>{{Kind::start_game}});
    // Up from the first row wraps to QUIT.
    EXPECT_EQ(f.keys({MenuKey::up, MenuKey::confirm}), std::vector<Request>{{Kind::quit}});
}

TEST(PlayMenus, TheHintNamesTheBoundKeys) {
    Fixture f;
    f.settings.keys[static_cast<std::size_t>(platform::Action::start)] = {
        platform::parse_key("K", nullptr).value()};
    f.menus.set_context(Context::title);
    EXPECT_NE(f.menus.page().hint.find("K SELECT"), std::string::npos) << f.menus.page().hint;
    f.menus.set_context(Context::paused);
    EXPECT_EQ(f.menus.page().hint.rfind("P / ESCAPE RESUME", 0), 0u) << f.menus.page().hint;
}

TEST(PlayMenus, LevelPageListsShippedAndUserLevelsAndChooses) {
    Fixture f;
    f.menus.set_context(Context::title);
    f.keys({MenuKey::down, MenuKey::confirm});
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::levels);
    const Page p = f.menus.page();
    EXPECT_EQ(labels(p), (std::vector<std::string>{"CLASSIC", "MAZE", "MINE", "BACK"}));
    EXPECT_EQ(p.rows[0].note, "PLAYING");
    EXPECT_EQ(p.rows[2].value, "YOUR LEVEL");
    const auto r = f.keys({MenuKey::down, MenuKey::down, MenuKey::confirm});
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].kind, Kind::choose_level);
    EXPECT_EQ(r[0].level, "/u/mine.toml");
    EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::title);
    // LEFT / RIGHT on the title's LEVEL row step through the levels too.
    const auto next = f.keys({MenuKey::right});
    ASSERT_EQ(next.size(), 1u);
    EXPECT_EQ(next[0].level, "/l/maze.toml");
}

TEST(PlayMenus, OptionsChangeTheSettingsAndAskToApplyThem) {
    Fixture f;
    f.menus.set_context(Context::title);
    f.keys({MenuKey::down, MenuKey::down, MenuKey::confirm});
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::options);
    EXPECT_EQ(labels(f.menus.page()),
              (std::vector<std::string>{"PRESET", "STYLE", "VOLUME", "FULLSCREEN", "VSYNC",
                                        "GAMEPAD LAYOUT", "SHOW FPS", "KEYS",
                                        "RESET KEYS TO DEFAULTS", "BACK"}));
    const std::vector<Request> changed{{Kind::settings_changed}};
    EXPECT_EQ(f.keys({MenuKey::right}), changed);
    EXPECT_EQ(f.settings.preset, "high");
    EXPECT_EQ(f.keys({MenuKey::right}), changed);
    EXPECT_EQ(f.settings.preset, "fast");  // wraps
    f.keys({MenuKey::down});
    f.keys({MenuKey::left});
    EXPECT_EQ(f.settings.style, "halo");  // every style of the table, wrapping from the first
    f.keys({MenuKey::right});
    f.keys({MenuKey::right});
    EXPECT_EQ(f.settings.style, "vector-xray");
    f.keys({MenuKey::down, MenuKey::left});
    EXPECT_NEAR(f.settings.volume, 0.7f, 1e-6);
    f.keys({MenuKey::down, MenuKey::confirm});
    EXPECT_TRUE(f.settings.fullscreen);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.vsync, platform::Vsync::adaptive);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.gamepad, platform::GamepadMode::drive);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_TRUE(f.settings.show_fps);
    // The save status shows under the rows.
    f.menus.env().save_status = "NOT SAVED: SETTINGS.TOML HAS ERRORS TO FIX FIRST";
    EXPECT_EQ(f.menus.page().lines.at(0), "NOT SAVED: SETTINGS.TOML HAS ERRORS TO FIX FIRST");
    // BACK returns to the title.
    f.keys({MenuKey::back});
    EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::title);
}

TEST(PlayMenus, VolumeStepsStopAtTheEndsAndWrap) {
    Fixture f;
    f.settings.volume = 0.95f;
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::options);
    f.keys({MenuKey::down, MenuKey::down, MenuKey::right});
    EXPECT_FLOAT_EQ(f.settings.volume, 1.0f);
    f.keys({MenuKey::right});
    EXPECT_FLOAT_EQ(f.settings.volume, 0.0f);
}

TEST(PlayMenus, RebindingCapturesAKeyAndShowsConflicts) {
    Fixture f;
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::options);
    f.keys({MenuKey::up, MenuKey::up, MenuKey::up, MenuKey::confirm});  // BACK, RESET, KEYS
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::keys);
    // Down to FIRE and ask to rebind it.
    for (int i = 0; i < static_cast<int>(platform::Action::fire); ++i) f.keys({MenuKey::down});
    EXPECT_EQ(f.menus.page().rows[f.menus.selected()].label, "FIRE");
    EXPECT_EQ(f.keys({MenuKey::confirm}), std::vector<Request>{{Kind::begin_capture}});
    EXPECT_TRUE(f.menus.capturing());
    EXPECT_EQ(f.menus.page().lines.at(0), "PRESS A KEY FOR FIRE");
    EXPECT_TRUE(f.keys({MenuKey::down}).empty());  // keys wait for the capture
    // P is pause's key: bound, and shown as a conflict on both rows.
    const platform::KeyBinding p{SDL_SCANCODE_P, platform::kModNone};
    EXPECT_EQ(f.menus.captured(p), std::vector<Request>{{Kind::settings_changed}});
    EXPECT_EQ(f.settings.keys[static_cast<std::size_t>(platform::Action::fire)],
              std::vector<platform::KeyBinding>{p});
    const Page page = f.menus.page();
    const Row& fire = page.rows[static_cast<std::size_t>(platform::Action::fire)];
    const Row& pause = page.rows[static_cast<std::size_t>(platform::Action::pause)];
    EXPECT_TRUE(fire.warn);
    EXPECT_EQ(fire.note, "ALSO PAUSE");
    EXPECT_TRUE(pause.warn);
    EXPECT_EQ(pause.note, "ALSO FIRE");
    EXPECT_NE(page.lines.at(0).find("ALSO BOUND TO PAUSE"), std::string::npos);
    // A cancelled capture changes nothing.
    f.keys({MenuKey::confirm});
    EXPECT_TRUE(f.menus.captured(platform::Input::kCaptureCancelled).empty());
    EXPECT_EQ(f.settings.keys[static_cast<std::size_t>(platform::Action::fire)],
              std::vector<platform::KeyBinding>{p});
    // RESET KEYS puts the defaults back.
    f.keys({MenuKey::back});
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::options);
    f.keys({MenuKey::down});  // KEYS -> RESET
    EXPECT_EQ(f.keys({MenuKey::confirm}), std::vector<Request>{{Kind::settings_changed}});
    EXPECT_EQ(f.settings.keys, platform::default_bindings());
}

TEST(PlayMenus, DefaultKeysHaveNoConflicts) {
    EXPECT_TRUE(platform::actions_in_conflict(platform::default_bindings()).empty());
}

TEST(PlayMenus, ControlsShowTheBoundKeysAndPadButtons) {
    Fixture f;
    f.settings.keys[static_cast<std::size_t>(platform::Action::fire)] = {
        platform::parse_key("Right Shift", nullptr).value()};
    f.menus.set_context(Context::paused);
    f.keys({MenuKey::down, MenuKey::down, MenuKey::confirm});
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::controls);
    const Page p = f.menus.page();
    const Row& fire = p.rows[static_cast<std::size_t>(platform::Action::fire)];
    EXPECT_EQ(fire.label, "FIRE");
    EXPECT_EQ(fire.value, "RIGHT SHIFT");
    EXPECT_EQ(fire.note, "A, R1, TRIGGERS");
    const Row& left = p.rows[static_cast<std::size_t>(platform::Action::left_tread_forward)];
    EXPECT_EQ(left.value, "Q");
    EXPECT_EQ(left.note, "LEFT STICK");
}

TEST(PlayMenus, PauseMenuResumesAndQuitsToTitle) {
    Fixture f;
    f.menus.set_context(Context::paused);
    EXPECT_EQ(labels(f.menus.page()),
              (std::vector<std::string>{"RESUME", "OPTIONS", "CONTROLS", "QUIT TO TITLE"}));
    EXPECT_EQ(f.keys({MenuKey::confirm}), std::vector<Request>{{Kind::resume}});
    EXPECT_EQ(f.keys({MenuKey::back}), std::vector<Request>{{Kind::resume}});  // P / Esc
    EXPECT_EQ(f.keys({MenuKey::up, MenuKey::confirm}), std::vector<Request>{{Kind::quit_to_title}});
    // A new context starts at its first page.
    f.menus.open_page(PlayMenus::Screen::options);
    f.menus.set_context(Context::none);
    EXPECT_FALSE(f.menus.open());
    EXPECT_TRUE(f.keys({MenuKey::confirm}).empty());
    f.menus.set_context(Context::paused);
    EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::paused);
    EXPECT_EQ(f.menus.selected(), 0u);
}

TEST(PlayMenus, HighScoresPageShowsTheTable) {
    Fixture f;
    f.scores.insert({"ZZZ", 99999999});
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::high_scores);
    const Page p = f.menus.page();
    ASSERT_GE(p.rows.size(), 2u);
    EXPECT_EQ(p.rows[0].label, "1.  ZZZ");
    EXPECT_EQ(p.rows[0].value, "99999999");
    EXPECT_FALSE(p.rows[0].selectable);
    EXPECT_EQ(p.rows.back().label, "BACK");
    EXPECT_EQ(p.rows[f.menus.selected()].label, "BACK");  // the entries cannot be chosen
    f.keys({MenuKey::down});
    EXPECT_EQ(p.rows[f.menus.selected()].label, "BACK");
}

TEST(PlayMenus, LongListsScrollToKeepTheSelectionInView) {
    EXPECT_EQ(scroll_window(5, 4, 10).first, 0u);
    EXPECT_EQ(scroll_window(5, 4, 10).count, 5u);
    EXPECT_EQ(scroll_window(30, 0, 10).first, 0u);
    EXPECT_EQ(scroll_window(30, 15, 10).first, 10u);
    EXPECT_EQ(scroll_window(30, 29, 10).first, 20u);
    for (std::size_t s = 0; s < 30; ++s) {
        const Window w = scroll_window(30, s, 10);
        EXPECT_LE(w.first, s);
        EXPECT_LT(s, w.first + w.count);
    }
}

TEST(PlayMenus, EveryPageDrawsInsideTheScreen) {
    const scene::VectorFont font = scene::VectorFont::load_default();
    Fixture f;
    for (const double aspect : {4.0 / 3.0, 16.0 / 9.0}) {
        for (const auto s : {PlayMenus::Screen::title, PlayMenus::Screen::levels,
                             PlayMenus::Screen::options, PlayMenus::Screen::keys,
                             PlayMenus::Screen::controls, PlayMenus::Screen::high_scores}) {
            f.menus.set_context(Context::none);
            f.menus.set_context(Context::title);
            if (s != PlayMenus::Screen::title) f.menus.open_page(s);
            for (int i = 0; i < 40; ++i) {
                std::vector<scene::HudLine> out;
                f.menus.draw(out, font, aspect, static_cast<std::uint64_t>(i));
                ASSERT_FALSE(out.empty());
                for (const scene::HudLine& l : out) {
                    for (const glm::vec2 q : {l.a, l.b}) {
                        ASSERT_LE(std::abs(q.x), aspect) << static_cast<int>(s) << " row " << i;
                        ASSERT_LE(std::abs(q.y), 1.0f) << static_cast<int>(s) << " row " << i;
                    }
                }
                f.keys({MenuKey::down});
            }
        }
    }
}

}  // namespace
}  // namespace bz::app::menu
