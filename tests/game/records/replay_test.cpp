#include "game/records/replay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "core/hash.h"
#include "core/io/file_io.h"
#include "core/rng.h"
#include "game/difficulty/autopilot.h"
#include "game/records/highscores.h"
#include "game/test_world.h"
#include "support/scratch_dir.h"

namespace bz::game {
namespace {

namespace fs = std::filesystem;

replay::Replay record_game(int ticks, std::uint64_t seed = 17) {
    const level::Level lv = default_level();
    World w = test::make_world(lv, seed);
    replay::Header h;
    h.seed = seed;
    h.level = kBuiltinLevelName;
    h.level_hash = replay::level_hash(lv);
    h.hash_interval = 60;
    replay::Recorder rec(h);
    for (int i = 0; i < ticks; ++i) {
        TickCommand c = autopilot(w);
        if (i % 200 < 50) c = test::drive(1.0f, 0.4f, c.fire);  // some driving too
        w.step(c);
        rec.record(c, w);
    }
    return rec.finish(w);
}

TEST(Replay, RecordedGameVerifies) {
    const replay::Replay r = record_game(60 * 60);
    EXPECT_EQ(r.commands.size(), 3600u);
    EXPECT_EQ(r.checks.size(), 60u);
    const auto v = replay::verify(r, default_level(), test::shared_assets());
    EXPECT_TRUE(v.ok);
    EXPECT_EQ(v.ticks, 3600u);
    EXPECT_EQ(v.checks_passed, 60u);
}

TEST(Replay, FinalHashIsAddedBetweenIntervals) {
    const replay::Replay r = record_game(130);
    ASSERT_EQ(r.checks.size(), 3u);
    EXPECT_EQ(r.checks.back().tick, 130u);
    EXPECT_TRUE(replay::verify(r, default_level(), test::shared_assets()).ok);
}

TEST(Replay, TamperedCommandFailsAtTheNextHash) {
    replay::Replay r = record_game(60 * 20);
    r.commands[125].left = static_cast<std::int8_t>(r.commands[125].left == 127 ? -127 : 127);
    const auto v = replay::verify(r, default_level(), test::shared_assets());
    EXPECT_FALSE(v.ok);
    ASSERT_TRUE(v.mismatch.has_value());
    EXPECT_EQ(v.mismatch->tick, 180u) << "the first hash after the change";
    EXPECT_EQ(v.checks_passed, 2u);
    EXPECT_NE(v.mismatch->expected, v.mismatch->actual);
}

TEST(Replay, TamperedHashOrSeedFails) {
    replay::Replay r = record_game(600);
    replay::Replay bad_hash = r;
    bad_hash.checks[4].hash ^= 1;
    auto v = replay::verify(bad_hash, default_level(), test::shared_assets());
    ASSERT_FALSE(v.ok);
    EXPECT_EQ(v.mismatch->tick, 300u);
    replay::Replay bad_seed = r;
    bad_seed.header.seed += 1;
    v = replay::verify(bad_seed, default_level(), test::shared_assets());
    ASSERT_FALSE(v.ok);
    EXPECT_EQ(v.mismatch->tick, 60u);
}

TEST(Replay, SerialiseParseRoundTripAndSaveIsAtomic) {
    const replay::Replay r = record_game(900);
    const std::string text = replay::serialise(r);
    const replay::Replay back = replay::parse(text, "mem");
    EXPECT_EQ(back.header.seed, r.header.seed);
    EXPECT_EQ(back.header.level, r.header.level);
    EXPECT_EQ(back.header.level_hash, r.header.level_hash);
    EXPECT_EQ(back.header.version, BEAMZONE_VERSION);
    ASSERT_EQ(back.commands.size(), r.commands.size());
    for (std::size_t i = 0; i < r.commands.size(); ++i)
        ASSERT_EQ(back.commands[i], r.commands[i]) << i;
    ASSERT_EQ(back.checks.size(), r.checks.size());
    EXPECT_TRUE(replay::verify(back, default_level(), test::shared_assets()).ok);
    // Run-length coding keeps held inputs small.
    EXPECT_LT(text.size(), 900u * 8u);

    const bz::test::ScratchDir dir("bz_replay_test");
    replay::save(dir.path() / "a.bzreplay", r);
    EXPECT_EQ(read_file(dir.path() / "a.bzreplay"), text);
}

// The nastier-missile rule is recorded: a new replay carries the world's, an old file (no line)
// plays with 0, never nastier, as it was played; the rule changes the game, so the header must
// carry it for a game where it mattered to verify.
TEST(Replay, TheNastierMissileRuleIsRecordedAndOldFilesPlayWithout) {
    replay::Replay r = record_game(300);
    EXPECT_EQ(r.header.missile_nastier_after, 25000);
    const std::string text = replay::serialise(r);
    EXPECT_NE(text.find("\nmissile-nastier-after 25000\n"), std::string::npos);
    EXPECT_EQ(replay::parse(text, "mem").header.missile_nastier_after, 25000);
    std::string old = text;
    old.erase(old.find("missile-nastier-after"),
              std::string("missile-nastier-after 25000\n").size());
    EXPECT_EQ(replay::parse(old, "mem").header.missile_nastier_after, 0);
    EXPECT_EQ(replay::serialise(replay::parse(old, "mem")), old) << "an old file round-trips";

    // Missiles only, from score 0, nastier after 1,000 points; the autopilot plays until a
    // nastier missile has flown a while.
    level::Level lv = test::empty_level();
    lv.enemies.missile = true;
    lv.enemies.slow_tank = true;
    lv.enemies.missile_score = 0;
    lv.enemies.missile_nastier_after = 1000;
    World w = test::make_world(lv, 23, 9);
    replay::Header h;
    h.seed = 23;
    h.level = "<test>";
    h.level_hash = replay::level_hash(lv);
    h.lives = 9;
    h.missile_nastier_after = w.rules().missile_nastier_after;
    replay::Recorder rec(h);
    int nasty_ticks = 0;
    for (int i = 0; i < 60 * 600 && nasty_ticks < 120 && !w.game_over(); ++i) {
        const TickCommand c = autopilot(w);
        w.step(c);
        rec.record(c, w);
        if (w.missile_is_nasty() && w.state().hostile &&
            w.state().hostile->kind == HostileKind::missile)
            ++nasty_ticks;
    }
    ASSERT_GE(nasty_ticks, 120) << "no nastier missile flew; score " << w.score();
    const replay::Replay game = replay::parse(replay::serialise(rec.finish(w)), "mem");
    EXPECT_TRUE(replay::verify(game, lv, test::shared_assets()).ok);
    replay::Replay without = game;
    without.header.missile_nastier_after = 0;
    EXPECT_FALSE(replay::verify(without, lv, test::shared_assets()).ok);
}

std::string replay_error(const std::string& text) {
    try {
        replay::parse(text, "r.bzr");
    } catch (const UserError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Replay, BadFilesGiveFileLineMessages) {
    const std::string good = replay::serialise(record_game(120));
    EXPECT_EQ(replay_error(""), "r.bzr:1:1: error: empty file, not a beamzone replay");
    EXPECT_NE(replay_error("hello\n").find("r.bzr:1:1: error: not a beamzone replay"),
              std::string::npos);
    EXPECT_NE(replay_error("beamzone-replay 9\n").find("r.bzr:1:17: error: replay format 9"),
              std::string::npos);
    // Cut short: drop the "end" line.
    EXPECT_NE(replay_error(good.substr(0, good.rfind("end"))).find("cut short"), std::string::npos);
    // A garbled command line names its line.
    std::string garbled = good;
    const auto c = garbled.find("\nc ");
    garbled.replace(c + 1, 3, "c x");
    const auto msg = replay_error(garbled);
    const auto line = 2 + std::count(garbled.begin(), garbled.begin() + static_cast<long>(c), '\n');
    EXPECT_NE(msg.find("r.bzr:" + std::to_string(line) + ":3: error: run length"),
              std::string::npos)
        << msg;
    // Out-of-range values and counts.
    std::string big = good;
    big.replace(big.find("ticks 120"), 9, "ticks 99999999999");
    EXPECT_NE(replay_error(big).find("over the limit"), std::string::npos);
    std::string tread = good;
    tread.insert(tread.find("\nh "), "\nc 1 300 0 00");
    EXPECT_NE(replay_error(tread).find("-127..127"), std::string::npos);
    EXPECT_NE(replay_error(good + "junk\n").find("after 'end'"), std::string::npos);
    std::string unknown = good;
    unknown.insert(unknown.find("seed"), "colour red\n");
    EXPECT_NE(replay_error(unknown).find("r.bzr:3:1: error: unknown record 'colour'"),
              std::string::npos);
}

TEST(Replay, LoadOfMissingFileIsAUserError) {
    EXPECT_THROW(replay::load("/nonexistent/x.bzreplay"), UserError);
}

TEST(Replay, LevelHashFollowsTheLevel) {
    level::Level a = default_level();
    level::Level b = default_level();
    EXPECT_EQ(replay::level_hash(a), replay::level_hash(b));
    b.obstacles[0].position.x += 1.0;
    EXPECT_NE(replay::level_hash(a), replay::level_hash(b));
    // A level from a file hashes the file's bytes.
    const bz::test::ScratchDir dir("bz_level_hash");
    const fs::path f = dir.path() / "level.toml";
    write_file_atomic(f, "version = 1\n");
    level::Level from_file = default_level();
    from_file.file = f;
    EXPECT_EQ(replay::level_hash(from_file), bz::hash_bytes("version = 1\n"));
}

}  // namespace
}  // namespace bz::game

namespace bz::game {
namespace {

// Random damage to a good file: every result parses or is refused with a UserError naming the
// file, and whatever parses can be verified without crashing.
TEST(Replay, MutatedFilesNeverCrash) {
    const std::string good = replay::serialise(record_game(300));
    Rng rng(123);
    int refused = 0, parsed = 0;
    for (int i = 0; i < 400; ++i) {
        std::string text = good;
        const int edits = 1 + static_cast<int>(rng.below(4));
        for (int e = 0; e < edits; ++e) {
            const auto at =
                static_cast<std::size_t>(rng.below(static_cast<std::uint32_t>(text.size())));
            switch (rng.below(3)) {
                case 0:
                    text[at] = static_cast<char>(rng.below(256));
                    break;
                case 1:
                    text.erase(at, 1 + rng.below(20));
                    break;
                default:
                    text.insert(
                        at, std::string(1 + rng.below(5), static_cast<char>('0' + rng.below(10))));
                    break;
            }
        }
        try {
            const replay::Replay r = replay::parse(text, "m.bzr");
            ++parsed;
            replay::verify(r, default_level(), test::shared_assets());
        } catch (const UserError& e) {
            ++refused;
            EXPECT_EQ(std::string(e.what()).rfind("m.bzr:", 0), 0u) << e.what();
        }
    }
    EXPECT_GT(refused, 100);
    EXPECT_EQ(refused + parsed, 400);
}

TEST(HighScoresFuzz, MutatedFilesNeverCrash) {
    HighScoreBook book;
    book.set(level_key("Classic", 42), HighScoreTable::defaults());
    const std::string good = serialise(book);
    Rng rng(7);
    for (int i = 0; i < 400; ++i) {
        std::string text = good;
        const auto at =
            static_cast<std::size_t>(rng.below(static_cast<std::uint32_t>(text.size())));
        text[at] = static_cast<char>(rng.below(256));
        const HighScoreParse back = parse_highscores(text, "h");
        for (const auto& kt : back.book.tables()) {
            EXPECT_LE(kt.second.entries().size(), HighScoreTable::kSize);
        }
        for (const std::string& e : back.errors) EXPECT_EQ(e.rfind("h:", 0), 0u) << e;
    }
}

}  // namespace
}  // namespace bz::game
