// Meaning errors (unknown keys, types, ranges, kinds, placement, version, caps), each at its
// exact position, and the values of a clean file.
#include <gtest/gtest.h>

#include <cmath>

#include "level/loader.h"
#include "level_test_util.h"

namespace bz::level {
namespace {

using test::has_one_error;
using test::level_text;

using test::load_text;

TEST(LoaderSchema, SmallestLevelGetsDefaults) {
    const auto r = load_text(level_text(""));
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    const Level& l = *r.level;
    EXPECT_EQ(l.version, 1);
    EXPECT_EQ(l.name, "Test level");
    EXPECT_EQ(l.field_size, 400.0);
    EXPECT_TRUE(l.wrap);
    EXPECT_TRUE(l.obstacles.empty());
    EXPECT_FALSE(l.backdrop.mountains.empty());  // the default skyline
    EXPECT_EQ(l.render.style, "vector");
    EXPECT_EQ(l.file, std::filesystem::path("levels/test.toml"));
}

TEST(LoaderSchema, ReadsEverySection) {
    const auto r = load_text(level_text(R"(author = "Ada"
description = "All keys."

[field]
size = 600
wrap = false
obstacle_color = "#ff0000"

[player]
position = [10, 0, -20]
heading = 90

[enemies]
types = ["slow_tank", "saucer"]
super_tank_score = 2000
missile_score = 3000
spawn_min_distance = 30
spawn_max_distance = 120
aggression = 0.75

[backdrop]
mountains = [[0, 2], [90, 5.5], [360, 2]]
volcano = false
volcano_azimuth = 10
moon = true
moon_azimuth = 200
moon_elevation = 30

[render]
style = "arcade"
preset = "high"
line_width = 3
crease_angle = 45
bloom_strength = 1.5

[[obstacle]]
kind = "pyramid"
position = [50, 0, 60]
heading = 45
scale = 2
color = [0.1, 0.2, 0.3]

[[obstacle]]
kind = "wall"
position = [-50, 0, 60]

[[camera_key]]
time = 0
eye = [0, 5, -100]
target = [0, 0, 0]

[[camera_key]]
time = 2.5
eye = [100, 5, 0]
target = [0, 0, 0]
)"));
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    const Level& l = *r.level;
    EXPECT_EQ(l.author, "Ada");
    EXPECT_EQ(l.description, "All keys.");
    EXPECT_EQ(l.field_size, 600.0);
    EXPECT_FALSE(l.wrap);
    EXPECT_EQ(l.player_start, glm::dvec3(10, 0, -20));
    EXPECT_EQ(l.player_heading_deg, 90.0);
    EXPECT_TRUE(l.enemies.slow_tank);
    EXPECT_FALSE(l.enemies.super_tank);
    EXPECT_FALSE(l.enemies.missile);
    EXPECT_TRUE(l.enemies.saucer);
    EXPECT_EQ(l.enemies.super_tank_score, 2000);
    EXPECT_EQ(l.enemies.missile_score, 3000);
    EXPECT_EQ(l.enemies.spawn_min_distance, 30.0);
    EXPECT_EQ(l.enemies.spawn_max_distance, 120.0);
    EXPECT_EQ(l.enemies.aggression, 0.75);
    ASSERT_EQ(l.backdrop.mountains.size(), 3u);
    EXPECT_EQ(l.backdrop.mountains[1], glm::dvec2(90, 5.5));
    EXPECT_FALSE(l.backdrop.volcano);
    EXPECT_EQ(l.backdrop.volcano_azimuth_deg, 10.0);
    EXPECT_EQ(l.backdrop.moon_azimuth_deg, 200.0);
    EXPECT_EQ(l.backdrop.moon_elevation_deg, 30.0);
    EXPECT_EQ(l.render.style, "arcade");
    EXPECT_EQ(l.render.preset, "high");
    EXPECT_EQ(l.render.line_width_px, 3.0);
    EXPECT_EQ(l.render.crease_angle_deg, 45.0);
    EXPECT_EQ(l.render.bloom_strength, 1.5);
    ASSERT_EQ(l.obstacles.size(), 2u);
    const ObjectDesc& p = l.obstacles[0];
    EXPECT_EQ(p.kind, "pyramid");
    EXPECT_EQ(p.position, glm::dvec3(50, 0, 60));
    EXPECT_EQ(p.heading_deg, 45.0);
    EXPECT_EQ(p.scale, 2.0);
    EXPECT_EQ(p.color, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_NEAR(p.footprint_radius, 2.0 * std::hypot(3.0, 3.0), 1e-9);
    EXPECT_EQ(p.pos.line, 38);
    EXPECT_EQ(p.pos.column, 1);
    // Obstacles without a colour take [field] obstacle_color; "#ff0000" is sRGB red.
    EXPECT_EQ(l.obstacles[1].color, glm::vec3(1.0f, 0.0f, 0.0f));
    ASSERT_EQ(l.camera_path.size(), 2u);
    EXPECT_EQ(l.camera_path[1].time, 2.5);
    EXPECT_EQ(l.camera_path[1].eye, glm::dvec3(100, 5, 0));
}

TEST(LoaderSchema, HexColourIsConvertedFromSrgb) {
    const auto r =
        load_text(level_text("[[obstacle]]\nkind = \"cube\"\nposition = [50, 0, 0]\n"
                             "color = \"#808080\"\n"));
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    EXPECT_NEAR(r.level->obstacles[0].color.r, 0.2158605f, 1e-5f);
}

TEST(LoaderSchema, UnknownKeySuggestsTheClosest) {
    const auto r = load_text(level_text("[field]\n  wrapp = true\n"));
    EXPECT_TRUE(has_one_error(r, 4, 3, "unknown key 'wrapp' in [field]; did you mean 'wrap'?"));
}

TEST(LoaderSchema, UnknownTableSuggestsTheClosest) {
    const auto r = load_text(level_text("[rendr]\nstyle = \"arcade\"\n"));
    EXPECT_TRUE(has_one_error(r, 3, 2, "did you mean 'render'?"));
}

TEST(LoaderSchema, UnknownKeyInObstacleSuggestsTheClosest) {
    const auto r =
        load_text(level_text("[[obstacle]]\nkind = \"cube\"\nposition = [50, 0, 0]\nheadng = 3\n"));
    EXPECT_TRUE(
        has_one_error(r, 6, 1, "unknown key 'headng' in obstacle 1; did you mean 'heading'?"));
}

TEST(LoaderSchema, TopLevelKeyBelowATableHeaderIsExplained) {
    const auto r = load_text(level_text("[render]\nstyle = \"arcade\"\nauthor = \"me\"\n"));
    EXPECT_TRUE(has_one_error(r, 5, 1,
                              "unknown key 'author' in [render]; 'author' belongs at the top "
                              "level: move it above the first [table] header"));
}

TEST(LoaderSchema, UnknownKeyFarFromAllGetsNoSuggestion) {
    const auto r = load_text(level_text("[field]\nzzzzzzzz = 1\n"));
    ASSERT_TRUE(has_one_error(r, 4, 1, "unknown key 'zzzzzzzz'"));
    EXPECT_EQ(r.errors[0].message.find("did you mean"), std::string::npos);
}

TEST(LoaderSchema, WrongTypes) {
    EXPECT_TRUE(has_one_error(load_text(level_text("[field]\nsize = \"big\"\n")), 4, 8,
                              "'size' must be a number, not a string"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[field]\nwrap = 1\n")), 4, 8,
                              "'wrap' must be true or false, not an integer"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\nmissile_score = 2.5\n")), 4, 17,
                              "'missile_score' must be a whole number, not a number"));
    EXPECT_TRUE(has_one_error(load_text(level_text("field = 3\n")), 3, 9,
                              "'field' must be a table ([field]), not an integer"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[obstacle]\nkind = \"cube\"\n")), 3, 1,
                              "'obstacle' must be a list of tables ([[obstacle]]), not a table"));
    EXPECT_TRUE(
        has_one_error(load_text(level_text("[player]\nposition = [1, 2]\n")), 4, 12,
                      "'position' must be an array of 3 numbers [x, y, z], not an array of 2"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nposition = [1, \"a\", 2]\n")), 4, 16,
                              "'position' y must be a number, not a string"));
    EXPECT_TRUE(has_one_error(load_text(level_text("name2 = 1\n")), 3, 1, "unknown key 'name2'"));
    EXPECT_TRUE(has_one_error(load_text("version = 1\nname = 5\n"), 2, 8,
                              "'name' must be a string, not an integer"));
}

TEST(LoaderSchema, OutOfRange) {
    EXPECT_TRUE(has_one_error(load_text(level_text("[field]\nsize = 10\n")), 4, 8,
                              "'size' must be between 50 and 10000, not 10"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\naggression = 1.5\n")), 4, 14,
                              "'aggression' must be between 0 and 1, not 1.5"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\nmissile_score = -1\n")), 4, 17,
                              "between 0 and 10000000, not -1"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[render]\nline_width = 0.1\n")), 4, 14,
                              "'line_width' must be between 0.5 and 16, not 0.1"));
    // Positions must lie on the field (half of size either side of the origin).
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nposition = [0, 0, 250]\n")), 4, 19,
                              "'position' z must be between -200 and 200, not 250"));
}

TEST(LoaderSchema, NanAndInfinity) {
    EXPECT_TRUE(has_one_error(load_text(level_text("[field]\nsize = nan\n")), 4, 8,
                              "'size' must be a finite number, not nan"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[field]\nsize = inf\n")), 4, 8,
                              "'size' must be a finite number, not inf"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nheading = -inf\n")), 4, 11,
                              "'heading' must be a finite number, not -inf"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nposition = [0, nan, 0]\n")), 4, 16,
                              "'position' y must be a finite number, not nan"));
}

TEST(LoaderSchema, UnknownObstacleKind) {
    const auto r = load_text(level_text("[[obstacle]]\nkind = \"cubee\"\nposition = [50, 0, 0]\n"));
    EXPECT_TRUE(has_one_error(r, 4, 8, "unknown kind 'cubee'; did you mean 'cube'?"));
}

TEST(LoaderSchema, MissingRequiredKeysAreReportedAtTheTable) {
    const auto r = load_text(level_text("\n[[obstacle]]\nheading = 3\n"));
    ASSERT_EQ(r.errors.size(), 2u);
    for (const auto& e : r.errors) {
        EXPECT_EQ(e.pos.line, 4);
        EXPECT_EQ(e.pos.column, 1);
    }
    EXPECT_NE(r.errors[0].message.find("obstacle 1 needs the key 'kind'"), std::string::npos);
    EXPECT_NE(r.errors[1].message.find("obstacle 1 needs the key 'position'"), std::string::npos);
    EXPECT_TRUE(has_one_error(load_text("version = 1\n"), 1, 1, "needs the key 'name'"));
}

TEST(LoaderSchema, ObstacleOverlappingThePlayerStart) {
    const auto r =
        load_text(level_text("[player]\nposition = [10, 0, 10]\n"
                             "[[obstacle]]\nkind = \"cube\"\nposition = [14, 0, 10]\n"));
    EXPECT_TRUE(has_one_error(r, 7, 12, "obstacle 1 (cube) overlaps the player start at (10, 10)"));
}

TEST(LoaderSchema, OverlapHonoursRotationScaleAndWrap) {
    // A wall 20 long: 8 units off its centre along its length is on it, unless turned 90 deg.
    const std::string wall = "[[obstacle]]\nkind = \"wall\"\nposition = [8, 0, 0]\n";
    EXPECT_FALSE(load_text(level_text(wall)).ok());
    EXPECT_TRUE(load_text(level_text(wall + "heading = 90\n")).ok());
    // A cube scaled 4 reaches 10 units out: 2 short of the start 12 units away.
    const std::string cube = "[[obstacle]]\nkind = \"cube\"\nposition = [12, 0, 0]\n";
    EXPECT_TRUE(load_text(level_text(cube)).ok());
    EXPECT_FALSE(load_text(level_text(cube + "scale = 4\n")).ok());
    // Across the edge of a wrapping field the start is 2 units from a cube at x = 199.
    const std::string edge =
        "[player]\nposition = [-199, 0, 0]\n"
        "[[obstacle]]\nkind = \"cube\"\nposition = [199, 0, 0]\n";
    EXPECT_FALSE(load_text(level_text(edge)).ok());
    EXPECT_TRUE(load_text(level_text("[field]\nwrap = false\n" + edge)).ok());
}

TEST(LoaderSchema, ABadValueDoesNotCascadeIntoChecksThatDependOnIt) {
    // A wrong field size is one error; positions are then not judged by a size nobody wrote.
    const auto size =
        load_text(level_text("[field]\nsize = 5\n"
                             "[[obstacle]]\nkind = \"cube\"\nposition = [300, 0, 0]\n"));
    EXPECT_TRUE(has_one_error(size, 4, 8, "'size' must be between 50 and 10000, not 5"));
    // A wrong start is one error; obstacles are not said to overlap the default start.
    const auto start =
        load_text(level_text("[player]\nposition = [0, nan, 0]\n"
                             "[[obstacle]]\nkind = \"cube\"\nposition = [1, 0, 0]\n"));
    EXPECT_TRUE(has_one_error(start, 4, 16, "'position' y must be a finite number, not nan"));
}

TEST(LoaderSchema, WrongVersion) {
    EXPECT_TRUE(has_one_error(load_text("version = 2\nname = \"x\"\n"), 1, 11,
                              "unsupported format version 2; this beamzone reads version 1"));
    EXPECT_TRUE(has_one_error(load_text("version = \"1\"\nname = \"x\"\n"), 1, 11,
                              "'version' must be a whole number, not a string"));
}

TEST(LoaderSchema, MissingOrLateVersion) {
    EXPECT_TRUE(has_one_error(load_text("# comment\n\nname = \"x\"\n"), 3, 1,
                              "the file must start with the format version: version = 1"));
    EXPECT_TRUE(has_one_error(load_text("name = \"x\"\nversion = 1\n"), 2, 11,
                              "'version' must be the first key in the file"));
    const auto empty = load_text("");
    ASSERT_EQ(empty.errors.size(), 2u);
    EXPECT_EQ(
        format(empty.errors[0]),
        "levels/test.toml:1:1: error: the file must start with the format version: version = 1");
    EXPECT_EQ(format(empty.errors[1]),
              "levels/test.toml:1:1: error: the top level needs the key 'name'");
}

TEST(LoaderSchema, WrongVersionStopsFurtherChecks) {
    // A file in another format would otherwise drown the one useful message in unknown keys.
    const auto r = load_text("version = 7\nname = \"x\"\n[teleporters]\nx = 1\n");
    EXPECT_TRUE(has_one_error(r, 1, 11, "unsupported format version 7"));
}

TEST(LoaderSchema, LineMethodTakesAutoAndReportsABadOneAtItsPosition) {
    for (const std::string m : {"compute", "geometry_shader", "auto", "geometry"}) {
        const auto r = load_text(level_text("[render]\nline_method = \"" + m + "\"\n"));
        ASSERT_TRUE(r.ok()) << m << ": " << format(r.errors.at(0));
        EXPECT_EQ(r.level->render.line_method, m);
    }
    EXPECT_TRUE(has_one_error(load_text(level_text("[render]\nline_method = \"automatic\"\n")), 4,
                              15, "'automatic'"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[render]\nline_method = \"computer\"\n")), 4,
                              15, "did you mean 'compute'"));
}

TEST(LoaderSchema, ReportsAllErrorsOfAFileInOrder) {
    const auto r =
        load_text(level_text("[field]\nsize = nan\nwrapp = true\n"
                             "[render]\nstyle = \"arcad\"\n"
                             "[[obstacle]]\nkind = \"cube\"\nposition = [0, 0, 1]\n"));
    ASSERT_EQ(r.errors.size(), 4u);
    EXPECT_EQ(r.errors[0].pos.line, 4);
    EXPECT_EQ(r.errors[1].pos.line, 5);
    EXPECT_EQ(r.errors[2].pos.line, 7);
    EXPECT_NE(r.errors[2].message.find("did you mean 'arcade'"), std::string::npos);
    EXPECT_EQ(r.errors[3].pos.line, 10);
    EXPECT_NE(r.errors[3].message.find("overlaps the player start"), std::string::npos);
}

TEST(LoaderSchema, EnemyTypes) {
    EXPECT_TRUE(
        has_one_error(load_text(level_text("[enemies]\ntypes = [\"slow_tank\", \"sacuer\"]\n")), 4,
                      23, "unknown enemy type 'sacuer'; did you mean 'saucer'?"));
    EXPECT_TRUE(
        has_one_error(load_text(level_text("[enemies]\ntypes = [\"saucer\", \"saucer\"]\n")), 4, 20,
                      "listed twice"));
    const auto none = load_text(level_text("[enemies]\ntypes = []\n"));
    ASSERT_TRUE(none.ok());
    EXPECT_FALSE(none.level->enemies.slow_tank || none.level->enemies.super_tank ||
                 none.level->enemies.missile || none.level->enemies.saucer);
}

TEST(LoaderSchema, SpawnDistancesMustBeOrdered) {
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\nspawn_min_distance = 80\n"
                                                   "spawn_max_distance = 50\n")),
                              5, 22, "must not be larger than spawn_max_distance"));
    // Defaults give way to what the author wrote.
    const auto only_max = load_text(level_text("[enemies]\nspawn_max_distance = 20\n"));
    ASSERT_TRUE(only_max.ok());
    EXPECT_EQ(only_max.level->enemies.spawn_min_distance, 20.0);
    const auto only_min = load_text(level_text("[enemies]\nspawn_min_distance = 150\n"));
    ASSERT_TRUE(only_min.ok());
    EXPECT_EQ(only_min.level->enemies.spawn_max_distance, 150.0);
    // On a small field the default spawn ring shrinks instead of failing.
    const auto small = load_text(level_text("[field]\nsize = 100\n"));
    ASSERT_TRUE(small.ok());
    EXPECT_EQ(small.level->enemies.spawn_max_distance, 50.0);
    EXPECT_LE(small.level->enemies.spawn_min_distance, 50.0);
}

TEST(LoaderSchema, MountainsMustIncreaseInAzimuth) {
    EXPECT_TRUE(
        has_one_error(load_text(level_text("[backdrop]\nmountains = [[0, 1], [50, 2], [40, 1]]\n")),
                      4, 32, "mountain azimuths must increase: 40 follows 50"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[backdrop]\nmountains = [[0, 1], [50]]\n")), 4,
                              22, "each mountain point must be [azimuth, height]"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[backdrop]\nmountains = [[0, 45], [10, 1]]\n")),
                              4, 18, "mountain height must be between 0 and 30, not 45"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[backdrop]\nmountains = []\n")), 4, 13,
                              "'mountains' needs at least 2 points; for a flat horizon"));
    const auto flat = load_text(level_text("[backdrop]\nmountains = [[0, 0], [360, 0]]\n"));
    ASSERT_TRUE(flat.ok());
    EXPECT_EQ(flat.level->backdrop.mountains.size(), 2u);
    const auto absent = load_text(level_text(""));
    ASSERT_TRUE(absent.ok());
    EXPECT_EQ(absent.level->backdrop.mountains, default_mountains());
}

TEST(LoaderSchema, CameraKeys) {
    const std::string key1 = "[[camera_key]]\ntime = 1\neye = [0, 5, 0]\ntarget = [0, 0, 50]\n";
    EXPECT_TRUE(has_one_error(load_text(level_text(key1 + key1)), 8, 8,
                              "camera key times must increase: 1 follows 1"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[[camera_key]]\ntime = 0\neye = [1, 2, 3]\n"
                                                   "target = [1, 2, 3]\n")),
                              6, 10, "camera target must differ from the eye"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[[camera_key]]\ntime = 0\neye = [1, 2, 3]\n")),
                              3, 1, "camera key 1 needs the key 'target'"));
}

// Two good keys whose path passes straight down (looking ahead, then behind, from above):
// the error names the second key's time and the moment the view is lost.
TEST(LoaderSchema, CameraPathBetweenKeysMustMakeAPicture) {
    const std::string ahead = "[[camera_key]]\ntime = 0\neye = [0, 50, 0]\ntarget = [0, 0, 10]\n";
    const std::string behind = "[[camera_key]]\ntime = 4\neye = [0, 50, 0]\ntarget = [0, 0, -10]\n";
    ASSERT_TRUE(load_text(level_text(ahead)).ok());
    ASSERT_TRUE(load_text(level_text(behind)).ok());
    EXPECT_TRUE(has_one_error(load_text(level_text(ahead + behind)), 8, 8,
                              "on the way to this key from the one before (at time 2) the camera "
                              "cannot make a picture"));
    // The eye driving through the target between two level keys.
    const std::string before = "[[camera_key]]\ntime = 0\neye = [0, 5, -10]\ntarget = [0, 5, 0]\n";
    const std::string after = "[[camera_key]]\ntime = 2\neye = [0, 5, 10]\ntarget = [0, 5, 0]\n";
    EXPECT_TRUE(
        has_one_error(load_text(level_text(before + after)), 8, 8, "the eye is at the target"));
    // Turning the other way round keeps the view level: no error.
    const std::string side = "[[camera_key]]\ntime = 4\neye = [0, 50, 0]\ntarget = [10, 0, 0]\n";
    EXPECT_TRUE(load_text(level_text(ahead + side)).ok());
}

TEST(LoaderSchema, StringLimits) {
    EXPECT_TRUE(
        has_one_error(load_text("version = 1\nname = \"\"\n"), 2, 8, "'name' must not be empty"));
    EXPECT_TRUE(has_one_error(load_text("version = 1\nname = \"" + std::string(65, 'x') + "\"\n"),
                              2, 8, "is 65 characters long; the limit is 64"));
    EXPECT_TRUE(
        has_one_error(load_text("version = 1\nname = \"a\\tb\"\n"), 2, 8, "control characters"));
}

TEST(LoaderSchema, ModelOnlyKeysOnBuiltinKinds) {
    const auto r =
        load_text(level_text("[[obstacle]]\nkind = \"cube\"\nposition = [50, 0, 0]\nradius = 4\n"));
    EXPECT_TRUE(has_one_error(r, 6, 10, "'radius' applies only to kind = \"model\""));
}

TEST(LoaderSchema, FileSizeCap) {
    LoadOptions options;
    options.max_file_bytes = 64;
    const std::string text = level_text("description = \"" + std::string(100, 'x') + "\"\n");
    const auto r = load_text(text, options);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(format(r.errors[0]), "levels/test.toml:1:1: error: file is " +
                                       std::to_string(text.size()) +
                                       " bytes, over the limit of 64");
}

TEST(LoaderSchema, CountCaps) {
    LoadOptions options;
    options.max_obstacles = 2;
    options.max_camera_keys = 1;
    options.max_mountain_points = 2;
    std::string body = "[backdrop]\nmountains = [[0, 1], [1, 1], [2, 1]]\n";  // line 4
    for (int i = 0; i < 3; ++i) body += "[[obstacle]]\nkind = \"cube\"\nposition = [50, 0, 0]\n";
    for (int i = 0; i < 2; ++i)
        body +=
            "[[camera_key]]\ntime = " + std::to_string(i) + "\neye = [0,1,0]\ntarget = [1,1,1]\n";
    const auto r = load_text(level_text(body), options);
    ASSERT_EQ(r.errors.size(), 3u);
    EXPECT_EQ(format(r.errors[0]),
              "levels/test.toml:4:13: error: too many mountain points: 3 (the limit is 2)");
    EXPECT_EQ(format(r.errors[1]),
              "levels/test.toml:5:1: error: too many obstacles: 3 (the limit is 2)");
    EXPECT_EQ(format(r.errors[2]),
              "levels/test.toml:14:1: error: too many camera keys: 2 (the limit is 1)");
}

TEST(LoaderSchema, ErrorFloodIsCapped) {
    LoadOptions options;
    options.max_errors = 5;
    std::string body = "[field]\n";
    for (int i = 0; i < 50; ++i) body += "bad" + std::to_string(i) + " = 1\n";
    const auto r = load_text(level_text(body), options);
    ASSERT_EQ(r.errors.size(), 6u);
    EXPECT_NE(r.errors.back().message.find("too many errors"), std::string::npos);
}

TEST(LoaderSchema, InlineTableObstaclesWork) {
    const auto r = load_text(
        level_text("obstacle = [\n  { kind = \"cube\", position = [50, 0, 0] },\n"
                   "  { kind = \"pyramid\", position = [-50, 0, 0], heading = 30 },\n]\n"));
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    ASSERT_EQ(r.level->obstacles.size(), 2u);
    EXPECT_EQ(r.level->obstacles[1].pos.line, 5);
    EXPECT_EQ(r.level->obstacles[1].pos.column, 3);
}

}  // namespace
}  // namespace bz::level
