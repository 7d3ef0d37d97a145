#include "app/play/menu/play_menus.h"

#include <SDL_gamecontroller.h>
#include <SDL_scancode.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "support/default_font.h"

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
        e.levels = {{"CLASSIC", "/l/classic.toml", false, "THE ARCADE FIELD."},
                    {"MAZE", "/l/maze.toml", false, "WALLS."},
                    {"MINE", "/u/mine.toml", true, ""}};
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
    EXPECT_EQ(p.lines, std::vector<std::string>{"THE ARCADE FIELD."});  // the selected one's
    f.keys({MenuKey::down});
    EXPECT_EQ(f.menus.page().lines, std::vector<std::string>{"WALLS."});
    // A long description breaks near its middle onto two lines, whole.
    f.menus.env().levels[1].description =
        "LEARN TO DRIVE AND SHOOT: A SMALL CALM FIELD, SLOW TANKS ONLY, NOTHING THAT HUNTS YOU.";
    EXPECT_EQ(f.menus.page().lines,
              (std::vector<std::string>{"LEARN TO DRIVE AND SHOOT: A SMALL CALM FIELD,",
                                        "SLOW TANKS ONLY, NOTHING THAT HUNTS YOU."}));
    f.keys({MenuKey::up});
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
              (std::vector<std::string>{"DIFFICULTY", "PRESET", "STYLE", "BEAM", "EFFECTS VOLUME",
                                        "FULLSCREEN", "VSYNC", "SHOW FPS", "FRAME RATE CAP",
                                        "COMFORT AND TEXT", "ARCADE SETTINGS", "GAMEPAD LAYOUT",
                                        "KEYS", "RESET KEYS AND BUTTONS", "BACK"}));
    const std::vector<Request> changed{{Kind::settings_changed}};
    EXPECT_EQ(f.keys({MenuKey::right}), changed);
    EXPECT_EQ(f.settings.difficulty, "easy");
    EXPECT_EQ(f.menus.page().rows[0].value, "EASY");
    f.keys({MenuKey::left, MenuKey::left});
    EXPECT_EQ(f.settings.difficulty, "arcade");  // wraps past the level's own
    f.keys({MenuKey::down});
    EXPECT_EQ(f.keys({MenuKey::right}), changed);
    EXPECT_EQ(f.settings.preset, "high");
    EXPECT_EQ(f.keys({MenuKey::right}), changed);
    EXPECT_EQ(f.settings.preset, "fast");  // wraps
    f.keys({MenuKey::down});
    f.keys({MenuKey::left});
    EXPECT_EQ(f.settings.style, "technical");  // every style of the table, wrapping from the first
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.beam, "classic");
    f.keys({MenuKey::down, MenuKey::left});
    EXPECT_NEAR(f.settings.volume, 0.7f, 1e-6);
    f.keys({MenuKey::down, MenuKey::confirm});
    EXPECT_TRUE(f.settings.fullscreen);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.vsync, platform::Vsync::adaptive);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_TRUE(f.settings.show_fps);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.max_fps, 30);
    EXPECT_EQ(f.keys({MenuKey::left, MenuKey::left}).size(), 2u);  // AUTO, then round to 240
    EXPECT_EQ(f.settings.max_fps, 240);
    EXPECT_EQ(f.menus.page().rows[8].value, "240");
    f.keys({MenuKey::down, MenuKey::down, MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.gamepad, platform::GamepadMode::drive);
    // The save status shows under the rows.
    f.menus.env().save_status = "NOT SAVED: SETTINGS.TOML HAS ERRORS TO FIX FIRST";
    EXPECT_EQ(f.menus.page().lines.at(0), "NOT SAVED: SETTINGS.TOML HAS ERRORS TO FIX FIRST");
    // BACK returns to the title.
    f.keys({MenuKey::back});
    EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::title);
}

TEST(PlayMenus, VsyncShowsWhatTheDriverGave) {
    Fixture f;
    f.menus.env().vsync_given = platform::Vsync::off;  // asked for "on", got "off"
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::options);
    const Row vsync = f.menus.page().rows[6];
    EXPECT_EQ(vsync.label, "VSYNC");
    EXPECT_EQ(vsync.note, "GOT OFF");
    EXPECT_TRUE(vsync.warn);
    f.menus.env().vsync_given = platform::Vsync::on;
    EXPECT_EQ(f.menus.page().rows[6].note, "");
}

TEST(PlayMenus, ComfortPageSetsTextSizeFlashesAndPalette) {
    Fixture f;
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::options);
    for (int i = 0; i < 9; ++i) f.keys({MenuKey::down});
    f.keys({MenuKey::confirm});
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::comfort);
    EXPECT_EQ(labels(f.menus.page()), (std::vector<std::string>{"TEXT SIZE", "FLICKER AND FLASHES",
                                                                "COLOUR-SAFE PALETTE", "BACK"}));
    const std::vector<Request> changed{{Kind::settings_changed}};
    EXPECT_EQ(f.keys({MenuKey::right}), changed);
    EXPECT_FLOAT_EQ(f.settings.ui_scale, 1.25f);
    EXPECT_EQ(f.menus.page().rows[0].value, "1.25X");
    f.keys({MenuKey::right, MenuKey::right, MenuKey::right});
    EXPECT_FLOAT_EQ(f.settings.ui_scale, 2.0f);
    f.keys({MenuKey::right});
    EXPECT_FLOAT_EQ(f.settings.ui_scale, 1.0f);  // wraps
    f.keys({MenuKey::left});
    EXPECT_FLOAT_EQ(f.settings.ui_scale, 2.0f);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.flashes, "soft");
    f.keys({MenuKey::confirm});
    EXPECT_EQ(f.settings.flashes, "off");
    f.keys({MenuKey::down, MenuKey::confirm});
    EXPECT_TRUE(f.settings.colour_safe);
    f.keys({MenuKey::back});
    EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::options);
}

TEST(PlayMenus, ArcadePageCyclesTheDipSwitchesFromTheLevelsOwn) {
    Fixture f;
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::arcade);
    EXPECT_EQ(labels(f.menus.page()),
              (std::vector<std::string>{"TANKS", "MISSILES FROM", "BONUS TANKS", "BACK"}));
    EXPECT_EQ(f.menus.page().rows[0].value, "LEVEL'S");
    f.keys({MenuKey::right});
    EXPECT_EQ(f.settings.arcade.lives, 2);
    f.keys({MenuKey::left, MenuKey::left});
    EXPECT_EQ(f.settings.arcade.lives, 5);  // past the level's own, to the last switch
    f.keys({MenuKey::down, MenuKey::right, MenuKey::right, MenuKey::right, MenuKey::right});
    EXPECT_EQ(f.settings.arcade.missile_score, 30000);
    f.keys({MenuKey::down, MenuKey::right});
    EXPECT_EQ(f.settings.arcade.bonus_score, 0);
    EXPECT_EQ(f.menus.page().rows[2].value, "NONE");
    f.keys({MenuKey::right});
    EXPECT_EQ(f.menus.page().rows[2].value, "15000 AND 100000");
    // From the pause menu the page says when they apply.
    f.menus.set_context(Context::paused);
    f.menus.open_page(PlayMenus::Screen::arcade);
    const auto& lines = f.menus.page().lines;
    EXPECT_NE(std::find(lines.begin(), lines.end(), "FROM THE NEXT GAME"), lines.end());
}

TEST(PlayMenus, VolumeStepsStopAtTheEndsAndWrap) {
    Fixture f;
    f.settings.volume = 0.95f;
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::options);
    f.keys({MenuKey::down, MenuKey::down, MenuKey::down, MenuKey::down, MenuKey::right});
    EXPECT_FLOAT_EQ(f.settings.volume, 1.0f);
    f.keys({MenuKey::right});
    EXPECT_FLOAT_EQ(f.settings.volume, 0.0f);
}

// The centre of row `row` as the menus place it.
glm::vec2 centre_of(const PlayMenus& m, std::size_t row, double aspect, float scale) {
    const Placement pl = place(bz::test::default_font(), m.page(), m.selected(), aspect, scale);
    for (const PlacedRow& r : pl.rows) {
        if (r.row == row) return 0.5f * (r.box.min + r.box.max);
    }
    ADD_FAILURE() << "row " << row << " is not shown";
    return {};
}

TEST(PlayMenus, MouseHoverSelectsClickChoosesWheelScrollsRightClickGoesBack) {
    for (const float scale : {1.0f, 2.0f}) {
        for (const double aspect : {4.0 / 3.0, 16.0 / 9.0}) {
            Fixture f;
            f.settings.ui_scale = scale;
            f.menus.set_context(Context::title);
            using P = PlayMenus::Pointer;
            // Hover over OPTIONS selects it; a click opens it.
            EXPECT_TRUE(f.menus
                            .pointer(P::move, centre_of(f.menus, 2, aspect, scale),
                                     bz::test::default_font(), aspect)
                            .empty());
            EXPECT_EQ(f.menus.selected(), 2u);
            f.menus.pointer(P::click, centre_of(f.menus, 2, aspect, scale),
                            bz::test::default_font(), aspect);
            ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::options);
            // Nothing under the pointer: nothing happens.
            f.menus.pointer(P::move, {0.0f, 0.99f}, bz::test::default_font(), aspect);
            EXPECT_EQ(f.menus.selected(), 0u);
            // The wheel steps down the list, stopping at its end.
            for (int i = 0; i < 30; ++i)
                f.menus.pointer(P::wheel_down, {}, bz::test::default_font(), aspect);
            EXPECT_EQ(f.menus.page().rows[f.menus.selected()].label, "BACK");
            f.menus.pointer(P::wheel_up, {}, bz::test::default_font(), aspect);
            EXPECT_EQ(f.menus.page().rows[f.menus.selected()].label, "RESET KEYS AND BUTTONS");
            // A click on a setting changes it.
            const auto fps = centre_of(f.menus, 7, aspect, scale);
            const auto r = f.menus.pointer(P::click, fps, bz::test::default_font(), aspect);
            EXPECT_EQ(r, std::vector<Request>{{Kind::settings_changed}});
            EXPECT_TRUE(f.settings.show_fps);
            // Right click goes back.
            f.menus.pointer(P::back, {}, bz::test::default_font(), aspect);
            EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::title);
        }
    }
}

TEST(PlayMenus, RowsNeverOverlapOrLeaveTheScreenAtAnyTextSize) {
    for (const float scale : {1.0f, 1.25f, 1.5f, 1.75f, 2.0f}) {
        for (const double aspect : {800.0 / 600.0, 16.0 / 9.0, 3840.0 / 2160.0, 21.0 / 9.0}) {
            Fixture f;
            f.settings.ui_scale = scale;
            for (const Context c : {Context::title, Context::paused}) {
                f.menus.set_context(c);
                for (const auto s : {PlayMenus::Screen::options, PlayMenus::Screen::comfort,
                                     PlayMenus::Screen::arcade, PlayMenus::Screen::controls,
                                     PlayMenus::Screen::keys}) {
                    f.menus.set_context(Context::none);
                    f.menus.set_context(c);
                    f.menus.open_page(s);
                    const Page p = f.menus.page();
                    const Placement pl =
                        place(bz::test::default_font(), p, f.menus.selected(), aspect, scale);
                    ASSERT_FALSE(pl.rows.empty());
                    const game::hud::Box footer = game::hud::footer_box(static_cast<float>(aspect));
                    for (std::size_t i = 0; i < pl.rows.size(); ++i) {
                        const auto& b = pl.rows[i].box;
                        EXPECT_GE(b.min.y, footer.max.y - 1e-4f) << p.title << " x" << scale;
                        EXPECT_LE(b.max.y, 1.0f) << p.title << " x" << scale;
                        EXPECT_LE(pl.label_x, b.min.x + 0.11f * scale);
                        EXPECT_GE(pl.label_x, -static_cast<float>(aspect)) << p.title;
                        if (i > 0) {
                            EXPECT_LE(b.max.y, pl.rows[i - 1].box.min.y + 1e-4f)
                                << p.title << " rows " << i - 1 << " and " << i;
                        }
                    }
                }
            }
        }
    }
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
    EXPECT_EQ(f.menus.page().lines.at(0), "PRESS A KEY OR A PAD BUTTON FOR FIRE");
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

// A pad button pressed while the keys page captures binds the button to the action: shown on
// the Keys and Controls pages, saved in the settings, and put back by RESET.
TEST(PlayMenus, RebindingCapturesAPadButton) {
    Fixture f;
    f.menus.set_context(Context::title);
    f.menus.open_page(PlayMenus::Screen::options);
    f.keys({MenuKey::up, MenuKey::up, MenuKey::up, MenuKey::confirm});  // BACK, RESET, KEYS
    ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::keys);
    for (int i = 0; i < static_cast<int>(platform::Action::fire); ++i) f.keys({MenuKey::down});
    EXPECT_EQ(f.menus.page().rows[f.menus.selected()].note, "A, R1");
    EXPECT_EQ(f.keys({MenuKey::confirm}), std::vector<Request>{{Kind::begin_capture}});
    EXPECT_EQ(f.menus.captured_button(SDL_CONTROLLER_BUTTON_X),
              std::vector<Request>{{Kind::settings_changed}});
    EXPECT_FALSE(f.menus.capturing());
    EXPECT_EQ(f.settings.buttons[static_cast<std::size_t>(platform::Action::fire)],
              std::vector<int>{SDL_CONTROLLER_BUTTON_X});
    EXPECT_EQ(f.menus.page().rows[f.menus.selected()].note, "X");
    EXPECT_EQ(f.menus.page().lines.at(0), "FIRE IS NOW BUTTON X");
    // Without a capture a button binds nothing.
    EXPECT_TRUE(f.menus.captured_button(SDL_CONTROLLER_BUTTON_Y).empty());
    f.keys({MenuKey::back, MenuKey::down});  // KEYS -> RESET
    EXPECT_EQ(f.keys({MenuKey::confirm}), std::vector<Request>{{Kind::settings_changed}});
    EXPECT_EQ(f.settings.buttons, platform::default_pad_bindings());
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
    EXPECT_EQ(fire.note, "A, R1, TRIGGERS");  // the default buttons, then the triggers
    const Row& left = p.rows[static_cast<std::size_t>(platform::Action::left_tread_forward)];
    EXPECT_EQ(left.value, "Q");
    EXPECT_EQ(left.note, "LEFT STICK");
}

TEST(PlayMenus, QuittingAGameWithAScoreAsksFirst) {
    for (const bool qualifies : {false, true}) {
        Fixture f;
        f.menus.env().score_at_stake = 12000;
        f.menus.env().score_qualifies = qualifies;
        f.menus.set_context(Context::paused);
        EXPECT_TRUE(f.keys({MenuKey::up, MenuKey::confirm}).empty()) << "not at once";
        ASSERT_EQ(f.menus.screen(), PlayMenus::Screen::confirm_quit);
        const Page p = f.menus.page();
        EXPECT_EQ(labels(p),
                  (std::vector<std::string>{
                      "KEEP PLAYING", qualifies ? "QUIT AND ENTER INITIALS" : "QUIT TO TITLE"}));
        ASSERT_FALSE(p.lines.empty());
        EXPECT_EQ(p.lines[0].rfind("SCORE 12000", 0), 0u) << p.lines[0];
        // KEEP PLAYING is first: the pause menu again.
        EXPECT_TRUE(f.keys({MenuKey::confirm}).empty());
        EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::paused);
        f.keys({MenuKey::confirm});
        EXPECT_EQ(f.menus.screen(), PlayMenus::Screen::confirm_quit);
        EXPECT_EQ(f.keys({MenuKey::down, MenuKey::confirm}),
                  std::vector<Request>{{Kind::quit_to_title}});
    }
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
