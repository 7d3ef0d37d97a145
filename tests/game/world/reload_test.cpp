// Hot reload into a running game: what stays (score, lives, screen, the tank, the hostile),
// what moves (things the new level puts inside an obstacle or off the field), determinism,
// recordings ending at the edit, meshes replaced in the same library, and bad levels refused
// with the game unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "game/difficulty/autopilot.h"
#include "game/game.h"
#include "game/test_world.h"
#include "game/world/collision.h"
#include "game/world/tuning.h"

namespace bz::game {
namespace {

using test::empty_level;
using test::object;

// True when a circle of `radius` at p overlaps one of the world's obstacles.
bool inside_obstacle(const World& w, glm::dvec2 p, double radius) {
    for (const scene::Entity& o : w.obstacles()) {
        const scene::Transform& t = o.transform;
        if (circle_hits(o.collider, t.yaw, t.scale, w.field().delta(ground(t.position), p),
                        radius)) {
            return true;
        }
    }
    return false;
}

glm::dvec2 player_at(const World& w) {
    return ground(w.state().player.body.transform.position);
}

GameOptions playing(std::uint64_t seed = 7) {
    GameOptions o;
    o.attract = false;
    o.seed = seed;
    return o;
}

// The built-in level with one more cube, far from where the tests drive.
level::Level edited(level::Level lv) {
    lv.obstacles.push_back(object("cube", 150.0, 150.0));
    return lv;
}

TEST(Reload, GameKeepsScoreLivesScreenTankAndHighScores) {
    GameOptions o = playing();
    o.highscores = HighScoreTable::defaults();
    Game g(default_level(), o);
    // Play with the autopilot until something has been shot.
    for (int i = 0; i < 60 * 60 * 5 && g.world()->score() == 0 && !g.world()->game_over(); ++i)
        g.tick(autopilot(*g.world()));
    ASSERT_GT(g.world()->score(), 0) << "the autopilot should score within five minutes";
    ASSERT_EQ(g.screen(), Screen::playing);
    const World& before = *g.world();
    const int score = before.score();
    const int lives = before.lives();
    const std::uint64_t tick = before.state().tick;
    const scene::Transform tank = before.state().player.body.transform;
    const scene::MeshLibrary* library = &g.meshes();
    const std::size_t obstacles = before.obstacles().size();

    const ReloadReport r = g.reload_level(edited(default_level()));
    ASSERT_NE(g.world(), nullptr);
    const World& after = *g.world();
    EXPECT_EQ(&after, &before) << "the same world goes on";
    EXPECT_EQ(after.score(), score);
    EXPECT_EQ(after.lives(), lives);
    EXPECT_EQ(after.state().tick, tick);
    EXPECT_EQ(g.screen(), Screen::playing);
    EXPECT_FALSE(r.world.player_moved);
    EXPECT_EQ(after.state().player.body.transform.position, tank.position);
    EXPECT_EQ(after.state().player.body.transform.yaw, tank.yaw);
    EXPECT_EQ(after.obstacles().size(), obstacles + 1);
    EXPECT_EQ(g.level().obstacles.size(), obstacles + 1);
    EXPECT_EQ(&g.meshes(), library) << "the renderer keeps its mesh cache";
    EXPECT_EQ(g.highscores().best(), o.highscores.best());
    EXPECT_FALSE(r.ended_recording.has_value()) << "nothing was being recorded";

    // And it plays on.
    for (int i = 0; i < 120; ++i) g.tick(autopilot(*g.world()));
    EXPECT_EQ(g.world()->state().tick, tick + 120);
    EXPECT_GE(g.world()->score(), score);
}

TEST(Reload, PausedStaysPausedAndAttractStaysAttract) {
    Game g(default_level(), playing());
    for (int i = 0; i < 30; ++i) g.tick(test::drive(1, 1));
    g.tick([] {
        TickCommand c;
        c.pause = true;
        return c;
    }());
    ASSERT_EQ(g.screen(), Screen::paused);
    g.reload_level(edited(default_level()));
    EXPECT_EQ(g.screen(), Screen::paused);

    Game a(default_level(), GameOptions{});
    for (int i = 0; i < 30; ++i) a.tick(TickCommand{});
    a.reload_level(edited(default_level()));
    EXPECT_EQ(a.screen(), Screen::attract);
    EXPECT_EQ(a.world(), nullptr);
    for (int i = 0; i < 30; ++i) a.tick(TickCommand{});
    EXPECT_FALSE(a.frame(0.5, 1.5).items.empty()) << "the demo plays on in the new level";
}

TEST(Reload, AnObstacleOnTheTankPushesItOut) {
    Game g(empty_level(), playing());
    for (int i = 0; i < 90; ++i) g.tick(test::drive(1, 0.8f));
    const glm::dvec2 at = player_at(*g.world());
    ASSERT_GT(glm::length(at), 1.0) << "it drove somewhere";

    level::Level lv = empty_level();
    lv.obstacles.push_back(object("cube", at.x + 0.5, at.y - 0.3));
    const ReloadReport r = g.reload_level(lv);
    const World& w = *g.world();
    EXPECT_TRUE(r.world.player_moved);
    const glm::dvec2 now = player_at(w);
    EXPECT_FALSE(inside_obstacle(w, now, tuning::kPlayerRadius));
    // The nearest free place: a cube is 5 x 5, so never much further than its corner.
    EXPECT_LT(glm::length(now - at), 2.5 * std::sqrt(2.0) + tuning::kPlayerRadius + 1.0);
    EXPECT_EQ(w.lives(), 3);
    EXPECT_EQ(w.phase(), Phase::playing);
    // Free to drive away: some direction is open.
    const glm::dvec2 from = player_at(w);
    bool moved = false;
    for (int i = 0; i < 240 && !moved; ++i) {
        g.tick(i < 120 ? test::drive(1, 1) : test::drive(-1, -1));
        moved = glm::length(player_at(*g.world()) - from) > 0.5;
    }
    EXPECT_TRUE(moved);
}

TEST(Reload, TankWrapsOrClampsOntoASmallerField) {
    World w = test::make_world(empty_level());
    test::run_until(
        w, [](const World&) { return test::drive(1, 1); },
        [](const World& x) { return glm::length(player_at(x)) > 60.0; }, 60 * 60);
    const glm::dvec2 was = player_at(w);
    ASSERT_GT(glm::length(was), 60.0);

    level::Level wrap = empty_level();
    wrap.field_size = 100.0;
    EXPECT_TRUE(w.reload_level(wrap, test::shared_assets().factories()).player_moved);
    glm::dvec2 p = player_at(w);
    EXPECT_LE(std::abs(p.x), 50.0);
    EXPECT_LE(std::abs(p.y), 50.0);
    EXPECT_NEAR(std::fmod(p.x - was.x + 1000.0, 100.0), 0.0, 1e-9) << "wrapped, not moved";

    level::Level closed = empty_level();
    closed.field_size = 40.0;
    closed.wrap = false;
    w.reload_level(closed, test::shared_assets().factories());
    p = player_at(w);
    EXPECT_TRUE(w.field().contains(p, tuning::kPlayerRadius));
    EXPECT_FALSE(w.field().wraps());
}

TEST(Reload, HostileStaysUnlessAnObstacleLandsOnIt) {
    World w = test::make_world(empty_level());
    w.spawn_hostile(HostileKind::slow_tank, {10.0, 40.0});
    ASSERT_TRUE(w.state().hostile.has_value());
    const Hostile h = *w.state().hostile;

    level::Level clear = empty_level();
    clear.obstacles.push_back(object("pyramid", -60.0, -60.0));
    const WorldReload kept = w.reload_level(clear, test::shared_assets().factories());
    EXPECT_FALSE(kept.hostile_moved);
    ASSERT_TRUE(w.state().hostile.has_value());
    EXPECT_EQ(w.state().hostile->id, h.id);
    EXPECT_EQ(w.state().hostile->body.transform.position, h.body.transform.position);

    const glm::dvec2 at = ground(h.body.transform.position);
    level::Level on_it = clear;
    on_it.obstacles.push_back(object("cube", at.x, at.y));
    const WorldReload moved = w.reload_level(on_it, test::shared_assets().factories());
    EXPECT_TRUE(moved.hostile_moved);
    ASSERT_TRUE(w.state().hostile.has_value()) << "an open field has room for it";
    const Hostile& now = *w.state().hostile;
    EXPECT_EQ(now.kind, HostileKind::slow_tank);
    EXPECT_FALSE(inside_obstacle(w, ground(now.body.transform.position), tuning::kTankRadius));
    EXPECT_GT(glm::length(ground(now.body.transform.position) - player_at(w)), 10.0);
}

TEST(Reload, ShellsOffAClosedFieldAreGone) {
    World w = test::make_world(empty_level());
    test::fire_and_wait(w, 40);  // the shell is now some 30 units ahead
    ASSERT_EQ(w.state().shells.size(), 1u);
    level::Level small = empty_level();
    small.field_size = 20.0;
    small.wrap = false;
    w.reload_level(small, test::shared_assets().factories());
    EXPECT_TRUE(w.state().shells.empty());
}

// Same seed, same commands, the same edit at the same tick: the same game. The edit drops a
// cube on the tank, so the nudge out of it is covered too.
std::uint64_t play_with_reload(int reload_tick, bool* player_moved = nullptr) {
    Game g(default_level(), playing(11));
    for (int i = 0; i < 1200; ++i) {
        if (i == reload_tick) {
            level::Level edit = edited(default_level());
            edit.enemies.aggression = 1.0;
            const glm::dvec2 at = player_at(*g.world());
            edit.obstacles.push_back(object("cube", at.x + 0.7, at.y));
            const ReloadReport r = g.reload_level(edit);
            if (player_moved) *player_moved = r.world.player_moved;
        }
        g.tick(autopilot(*g.world()));
    }
    return g.world()->state_hash();
}

TEST(Reload, DeterministicForTheSameTick) {
    bool moved = false;
    const std::uint64_t a = play_with_reload(400, &moved);
    EXPECT_TRUE(moved);
    EXPECT_EQ(a, play_with_reload(400));
    EXPECT_EQ(play_with_reload(900), play_with_reload(900));
    EXPECT_NE(a, play_with_reload(-1)) << "the reload changes the game";
}

TEST(Reload, EndsARecordingThatStillVerifies) {
    GameOptions o = playing(5);
    o.record = true;
    Game g(default_level(), o);
    for (int i = 0; i < 300; ++i) g.tick(autopilot(*g.world()));
    const std::uint64_t hash = g.world()->state_hash();

    const ReloadReport r = g.reload_level(edited(default_level()));
    ASSERT_TRUE(r.ended_recording.has_value());
    EXPECT_EQ(r.ended_recording->commands.size(), 300u);
    ASSERT_FALSE(r.ended_recording->checks.empty());
    EXPECT_EQ(r.ended_recording->checks.back().tick, 300u);
    EXPECT_EQ(r.ended_recording->checks.back().hash, hash) << "the old level's last state";
    EXPECT_EQ(r.ended_recording->header.level_hash, replay::level_hash(default_level()));
    EXPECT_TRUE(replay::verify(*r.ended_recording, default_level(), test::shared_assets()).ok);

    // Later ticks (and games) are not added to it.
    for (int i = 0; i < 100; ++i) g.tick(autopilot(*g.world()));
    ASSERT_TRUE(g.recording().has_value());
    EXPECT_EQ(g.recording()->commands.size(), 300u);
}

TEST(Reload, RefusedDuringAReplay) {
    GameOptions o = playing(3);
    o.record = true;
    Game rec(default_level(), o);
    for (int i = 0; i < 120; ++i) rec.tick(autopilot(*rec.world()));
    Game g(default_level(), GameOptions{});
    g.start_replay(*rec.recording());
    for (int i = 0; i < 60; ++i) g.tick(TickCommand{});
    EXPECT_THROW(g.reload_level(edited(default_level())), UserError);
    for (int i = 0; i < 100 && !g.replay_finished(); ++i) g.tick(TickCommand{});
    EXPECT_TRUE(g.replay_finished());
    EXPECT_FALSE(g.replay_mismatch().has_value());
}

TEST(Reload, BadLevelChangesNothing) {
    Game g(default_level(), playing());
    for (int i = 0; i < 60; ++i) g.tick(autopilot(*g.world()));
    const std::uint64_t hash = g.world()->state_hash();
    const std::size_t meshes = g.meshes().size();

    level::Level unknown = edited(default_level());
    unknown.obstacles.back().kind = "nonesuch";
    unknown.obstacles.back().pos = {"lv.toml", 12, 8};
    try {
        g.reload_level(unknown);
        ADD_FAILURE() << "an unknown kind must be refused";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("lv.toml:12:8: error:"), std::string::npos)
            << e.what();
    }
    level::Level missing_model = edited(default_level());
    missing_model.obstacles.back().kind = "model";
    missing_model.obstacles.back().model = "/nonexistent/thing.obj";
    EXPECT_THROW(g.reload_level(missing_model), UserError);
    level::Level no_field = edited(default_level());
    no_field.field_size = 0.0;
    EXPECT_THROW(g.reload_level(no_field), UserError);

    EXPECT_EQ(g.world()->state_hash(), hash);
    EXPECT_EQ(g.meshes().size(), meshes);
    EXPECT_EQ(g.level().obstacles.size(), default_level().obstacles.size());
}

void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file) << text;
}

TEST(Reload, ChangedMeshesAreReplacedInTheSameLibrary) {
    const std::filesystem::path dir =
        std::filesystem::path(::testing::TempDir()) / "beamzone_reload_test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path obj = dir / "wedge.obj";
    write_text(obj, "v 0 0 0\nv 2 0 0\nv 0 0 2\nv 0 2 0\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");

    level::Level lv = empty_level();
    level::ObjectDesc m = object("model", 30.0, -30.0);
    m.model = obj;
    lv.obstacles.push_back(m);
    Game g(lv, playing());
    const scene::MeshLibrary& lib = g.meshes();
    const scene::MeshId model = *lib.find(obj.string());
    const scene::MeshId mountains = *lib.find("game:mountains");
    const std::uint32_t model_v = lib.version(model);
    const std::uint32_t mountains_v = lib.version(mountains);

    // Nothing changed: no new versions (no needless uploads).
    g.reload_level(lv);
    EXPECT_EQ(lib.version(model), model_v);
    EXPECT_EQ(lib.version(mountains), mountains_v);

    // A bigger model and a new skyline: same ids, new versions, and the collider follows.
    write_text(obj, "v 0 0 0\nv 6 0 0\nv 0 0 6\nv 0 6 0\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
    level::Level next = lv;
    next.backdrop.mountains = {{0.0, 2.0}, {90.0, 6.0}, {200.0, 3.0}};
    g.reload_level(next);
    EXPECT_EQ(&g.meshes(), &lib);
    EXPECT_EQ(*lib.find(obj.string()), model);
    EXPECT_EQ(lib.version(model), model_v + 1);
    EXPECT_EQ(lib.version(mountains), mountains_v + 1);
    ASSERT_EQ(g.world()->obstacles().size(), 1u);
    EXPECT_EQ(g.world()->obstacles()[0].mesh, model);
    EXPECT_NEAR(g.world()->obstacles()[0].collider.half_extent.x, 6.0, 1e-6);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace bz::game
