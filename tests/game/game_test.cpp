// The Game facade: screens from attract through play, pause, game over, initials and the
// high-score table; recording and replaying through it; sounds; what a frame holds.
#include "game/game.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "game/difficulty/autopilot.h"
#include "game/world/tuning.h"
#include "support/default_font.h"
#include "test_world.h"

namespace bz::game {
namespace {

TickCommand press(bool TickCommand::*button) {
    TickCommand c;
    c.*button = true;
    return c;
}

// Taps a button: one tick down, one tick up.
void tap(Game& g, bool TickCommand::*button) {
    g.tick(press(button));
    g.tick(TickCommand{});
}

// Plays with the autopilot until the game is over.
void play_out(Game& g, int max_ticks = 60 * 60 * 30) {
    for (int i = 0; i < max_ticks && g.screen() == Screen::playing; ++i)
        g.tick(autopilot(*g.world()));
}

HighScoreTable low_table() {
    HighScoreTable t;
    for (int i = 0; i < 10; ++i) t.insert({"LOW", 10 + i});
    return t;
}

TEST(Game, AttractStartPauseResume) {
    GameOptions o;
    Game g(default_level(), o, &bz::test::default_font());
    EXPECT_EQ(g.screen(), Screen::attract);
    EXPECT_EQ(g.world(), nullptr);
    for (int i = 0; i < 120; ++i) g.tick(TickCommand{});
    EXPECT_EQ(g.screen(), Screen::attract);
    scene::FrameList f = g.frame(0.5, 16.0 / 9.0);
    EXPECT_FALSE(f.items.empty()) << "the demo plays behind the title";
    EXPECT_FALSE(g.shows_live_world()) << "the demo's tank, not the player's";
    EXPECT_FALSE(f.hud.empty());
    EXPECT_EQ(g.sounds().engine, 0.0f);

    tap(g, &TickCommand::start);
    ASSERT_EQ(g.screen(), Screen::playing);
    ASSERT_NE(g.world(), nullptr);
    // The camera cuts to the player's tank (the play session marks that frame a cut).
    EXPECT_TRUE(g.shows_live_world());
    for (int i = 0; i < 30; ++i) g.tick(test::drive(1, 1));
    EXPECT_GT(g.sounds().engine, 0.5f);
    const std::uint64_t tick = g.world()->state().tick;

    tap(g, &TickCommand::pause);
    ASSERT_EQ(g.screen(), Screen::paused);
    EXPECT_TRUE(g.shows_live_world()) << "paused: the same camera, no cut";
    for (int i = 0; i < 100; ++i) g.tick(test::drive(1, 1, i % 2 == 0));
    EXPECT_EQ(g.world()->state().tick, tick) << "nothing moves while paused";
    EXPECT_EQ(g.sounds().engine, 0.0f);
    // Holding pause does not flicker: it acts on the press.
    g.tick(press(&TickCommand::pause));
    EXPECT_EQ(g.screen(), Screen::playing);
    g.tick(press(&TickCommand::pause));
    EXPECT_EQ(g.screen(), Screen::playing);
}

TEST(Game, GameOverInitialsAndTable) {
    GameOptions o;
    o.lives = 1;
    o.highscores = low_table();
    Game g(default_level(), o, &bz::test::default_font());
    tap(g, &TickCommand::start);
    play_out(g);
    ASSERT_EQ(g.screen(), Screen::game_over)
        << "score " << g.world()->score() << " at tick " << g.world()->state().tick;
    const int score = g.world()->score();
    ASSERT_GT(score, 19) << "the autopilot scores before it is shot";
    EXPECT_FALSE(g.frame(0.0, 1.5).hud.empty());
    for (int i = 0; i < 4 * 60 + 1 && g.screen() == Screen::game_over; ++i) g.tick(TickCommand{});
    ASSERT_EQ(g.screen(), Screen::enter_initials);

    // C: up twice then fire.
    tap(g, &TickCommand::up);
    tap(g, &TickCommand::up);
    tap(g, &TickCommand::fire);
    // A mistake (down from A wraps to space), erased with back.
    tap(g, &TickCommand::down);
    tap(g, &TickCommand::fire);
    tap(g, &TickCommand::back);
    EXPECT_EQ(g.screen(), Screen::enter_initials);
    // A: up from space; B: up, fire.
    tap(g, &TickCommand::up);
    tap(g, &TickCommand::fire);
    tap(g, &TickCommand::up);
    tap(g, &TickCommand::fire);
    ASSERT_EQ(g.screen(), Screen::high_scores);
    EXPECT_EQ(g.highscores().entries()[0].initials, "CAB");
    EXPECT_EQ(g.highscores().entries()[0].score, score);
    EXPECT_TRUE(g.take_highscores_changed());
    EXPECT_FALSE(g.take_highscores_changed()) << "reported once";
    for (int i = 0; i < 8 * 60 + 1; ++i) g.tick(TickCommand{});
    EXPECT_EQ(g.screen(), Screen::attract);
}

TEST(Game, ScoreThatMissesTheTableSkipsInitials) {
    GameOptions o;
    o.lives = 1;
    o.attract = false;
    o.difficulty = level::Difficulty::arcade;  // so that the autopilot's game ends soon
    HighScoreTable high;
    for (int i = 0; i < 10; ++i) high.insert({"TOP", 90'000'000});
    o.highscores = high;
    Game g(default_level(), o);
    ASSERT_EQ(g.screen(), Screen::playing);
    play_out(g);
    for (int i = 0; i < 4 * 60 + 1 && g.screen() == Screen::game_over; ++i) g.tick(TickCommand{});
    EXPECT_EQ(g.screen(), Screen::high_scores);
    EXPECT_FALSE(g.take_highscores_changed());
}

TEST(Game, QuitFromPauseEndsTheGame) {
    GameOptions o;
    o.attract = false;
    Game g(default_level(), o);
    tap(g, &TickCommand::pause);
    tap(g, &TickCommand::back);
    EXPECT_EQ(g.screen(), Screen::game_over);
}

TEST(Game, RecordingVerifiesAndReplaysThroughTheGame) {
    GameOptions o;
    o.attract = false;
    o.record = true;
    o.seed = 42;
    o.lives = 2;
    Game g(default_level(), o);
    EXPECT_EQ(g.recording()->commands.size(), 0u);
    std::vector<SoundEvent> heard;
    for (int i = 0; i < 60 * 90 && g.screen() == Screen::playing; ++i) {
        TickCommand c = autopilot(*g.world());
        if (i == 600) c.pause = true;  // a pause: those ticks are not part of the game
        g.tick(c);
        if (g.screen() == Screen::paused) {
            for (int k = 0; k < 30; ++k) g.tick(TickCommand{});
            tap(g, &TickCommand::pause);
        }
        heard.insert(heard.end(), g.sounds().events.begin(), g.sounds().events.end());
    }
    EXPECT_TRUE(test::has(heard, SoundEvent::shot));
    EXPECT_TRUE(test::has(heard, SoundEvent::radar_blip));
    const std::optional<replay::Replay> rec = g.recording();
    ASSERT_TRUE(rec.has_value());
    EXPECT_EQ(rec->header.seed, 42u);
    EXPECT_EQ(rec->header.level, kBuiltinLevelName);
    EXPECT_EQ(rec->header.lives, 2);
    EXPECT_EQ(rec->commands.size(), g.world()->state().tick);
    ASSERT_FALSE(rec->checks.empty());
    EXPECT_EQ(rec->checks.back().tick, g.world()->state().tick);
    EXPECT_EQ(rec->checks.back().hash, g.world()->state_hash());

    const replay::Replay parsed = replay::parse(replay::serialise(*rec), "mem");
    EXPECT_TRUE(replay::verify(parsed, default_level(), test::shared_assets()).ok);

    // Played back inside a Game: same end state, no mismatch, the live input ignored.
    Game p(default_level(), GameOptions{}, &bz::test::default_font());
    p.start_replay(parsed);
    ASSERT_EQ(p.screen(), Screen::playing);
    for (int i = 0; i < 60 * 120 && !p.replay_finished(); ++i) p.tick(test::drive(1, -1, true));
    EXPECT_TRUE(p.replay_finished()) << p.world()->state().tick << " of " << parsed.commands.size()
                                     << " screen " << static_cast<int>(p.screen());
    EXPECT_FALSE(p.replay_mismatch().has_value());
    EXPECT_EQ(p.world()->state_hash(), g.world()->state_hash());
    EXPECT_FALSE(p.frame(1.0, 1.5).hud.empty());

    // A tampered replay is caught during playback too.
    replay::Replay bad = parsed;
    bad.commands[10].left = 127;
    bad.commands[10].right = -127;
    Game q(default_level(), GameOptions{});
    q.start_replay(bad);
    for (int i = 0; i < 60 * 120 && q.screen() == Screen::playing; ++i) q.tick(TickCommand{});
    ASSERT_TRUE(q.replay_mismatch().has_value());
    EXPECT_EQ(q.replay_mismatch()->tick, 60u);

    // A replay of another level is refused with a clear message.
    level::Level other = default_level();
    other.obstacles.pop_back();
    Game r(other, GameOptions{});
    EXPECT_THROW(r.start_replay(parsed), UserError);
}

TEST(Game, QuitToTitleEntersAQualifyingScoreFirst) {
    for (const bool qualifies : {true, false}) {
        GameOptions o;
        o.attract = false;
        o.seed = 5;
        if (qualifies) {
            o.highscores = low_table();
        } else {
            HighScoreTable high;
            for (int i = 0; i < 10; ++i) high.insert({"TOP", 9'000'000 + i});
            o.highscores = high;
        }
        Game g(default_level(), o, &bz::test::default_font());
        for (int i = 0; i < 60 * 180 && g.world()->score() == 0; ++i) {
            g.tick(autopilot(*g.world()));
        }
        ASSERT_GT(g.world()->score(), 0) << "the autopilot scored nothing";
        ASSERT_EQ(g.screen(), Screen::playing);
        EXPECT_EQ(g.score_qualifies(), qualifies);
        g.quit_to_title();
        if (qualifies) {
            ASSERT_EQ(g.screen(), Screen::enter_initials);
            for (int k = 0; k < 3; ++k) tap(g, &TickCommand::fire);
            EXPECT_EQ(g.screen(), Screen::high_scores);
            EXPECT_TRUE(g.take_highscores_changed());
            EXPECT_EQ(g.highscores().entries().front().score, g.world()->score());
        } else {
            EXPECT_EQ(g.screen(), Screen::attract);
            EXPECT_FALSE(g.take_highscores_changed());
        }
    }
}

TEST(Game, FrameHoldsWorldHorizonAndHud) {
    GameOptions o;
    o.attract = false;
    Game g(default_level(), o, &bz::test::default_font());
    for (int i = 0; i < 10; ++i) g.tick(TickCommand{});
    const scene::FrameList f = g.frame(0.5, 4.0 / 3.0);
    EXPECT_NEAR(f.camera.eye.y, tuning::kEyeHeight, 1e-9);
    EXPECT_DOUBLE_EQ(f.camera.fov_y_deg, 45.0);
    bool mountains = false, landmark = false;
    for (const scene::DrawItem& item : f.items) {
        const std::string& name = g.meshes().name(item.mesh);
        mountains |= name == "game:mountains";
        landmark |= name == "builtin:pyramid";
        ASSERT_LT(item.mesh, g.meshes().size());
    }
    EXPECT_TRUE(mountains);
    EXPECT_TRUE(landmark);
    EXPECT_GT(f.hud.size(), 100u) << "radar, reticle and text";
}

}  // namespace
}  // namespace bz::game
