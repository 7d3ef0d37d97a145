#pragma once
// Replays: the seed, the level's hash, the build version and every tick's command, plus the
// world's state hash every N ticks so a re-run can prove it reproduced the game exactly.
//
// File format (text, one record per line, '#' starts a comment line):
//   beamzone-replay 1
//   version 0.1.0          build that recorded it (BEAMZONE_VERSION)
//   seed 42
//   level levels/classic.toml   (or builtin:default)
//   level-hash 0123456789abcdef
//   lives 3
//   difficulty normal      optional (older files: normal)
//   missile-score 30000    optional: the arcade setting it was played with (else the level's)
//   bonus-score 0          optional: the first bonus tank, 0 none (else the level's)
//   missile-nastier-after 25000  optional: the nastier-missile rule it was played with
//                          (level::EnemyRules::missile_nastier_after); absent: 0, never, as
//                          every game recorded before the rule existed was played
//   hash-interval 60
//   ticks 3600
//   c COUNT LEFT RIGHT BUTTONS   a run of COUNT identical commands (treads -127..127, buttons hex)
//   h TICK HASH                  state hash after TICK ticks (hex)
//   end                          absent = the file was cut short
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "game/world/tick_command.h"
#include "game/world/world.h"
#include "level/level.h"

namespace bz::game {
class Assets;
}

namespace bz::game::replay {

inline constexpr int kFormatVersion = 1;
// Ten hours of play: a larger count in a file is an error, not an allocation.
inline constexpr std::uint64_t kMaxTicks = 60ull * 60 * 60 * 10;

struct Header {
    std::string version = BEAMZONE_VERSION;
    std::uint64_t seed = 0;
    std::string level;  // path as given to the game, or kBuiltinLevelName
    std::uint64_t level_hash = 0;
    int lives = 3;
    level::Difficulty difficulty = level::Difficulty::normal;
    std::optional<int> missile_score;  // arcade settings (game/difficulty/arcade_rules.h)
    std::optional<int> bonus_score;
    // A new recording takes the world's (World::rules()); a file without the line reads 0.
    int missile_nastier_after = level::EnemyRules{}.missile_nastier_after;
    int hash_interval = 60;
};

struct StateCheck {
    std::uint64_t tick = 0;
    std::uint64_t hash = 0;
};

struct Replay {
    Header header;
    std::vector<PackedCommand> commands;  // one per tick
    std::vector<StateCheck> checks;       // increasing ticks
};

std::string serialise(const Replay& replay);
// `name` is used in messages: "NAME:LINE: error: ...". Throws UserError.
Replay parse(std::string_view text, const std::string& name);
Replay load(const std::filesystem::path& file);
// Written atomically: an interrupted save leaves the previous file intact.
void save(const std::filesystem::path& file, const Replay& replay);

// FNV-1a of the level file's bytes; for a level without a file (the built-in one) a hash of
// everything in it that the simulation reads.
std::uint64_t level_hash(const level::Level& level);

// Records while a game is played: call record() after every World::step with the command
// that was stepped.
class Recorder {
  public:
    explicit Recorder(Header header);
    void record(const TickCommand& command, const World& after);
    // The replay so far, with the final state's hash added when it fell between intervals.
    Replay finish(const World& world) const;
    const Replay& replay() const { return replay_; }

  private:
    Replay replay_;
};

struct Mismatch {
    std::uint64_t tick = 0;
    std::uint64_t expected = 0;
    std::uint64_t actual = 0;
};

// Plays a replay back: next() gives each recorded command in turn; after stepping the world
// with it, check() compares the state hash recorded for that tick (if any).
class Player {
  public:
    explicit Player(Replay replay);
    bool done() const { return next_ >= replay_.commands.size(); }
    std::size_t position() const { return next_; }
    TickCommand next();
    std::optional<Mismatch> check(const World& world);
    const Replay& replay() const { return replay_; }
    std::size_t checks_passed() const { return checks_passed_; }

  private:
    Replay replay_;
    std::size_t next_ = 0;
    std::size_t next_check_ = 0;
    std::size_t checks_passed_ = 0;
};

struct VerifyResult {
    bool ok = false;
    std::uint64_t ticks = 0;  // ticks simulated
    std::size_t checks_passed = 0;
    std::optional<Mismatch> mismatch;  // the first one; the run stops there
};

// Why checking `replay`'s state hashes would not prove all of it: empty when it has a hash at
// every multiple of its hash interval and at its last tick, as every recording has; else what is
// missing ("no state hashes", "no hash at tick 120 ..."). A replay whose hashes were stripped
// or thinned would otherwise "verify" with nothing compared.
std::string missing_state_hashes(const Replay& replay);

// The level as the replay's game played it: its difficulty, its arcade settings and its
// nastier-missile rule applied to `level`.
level::Level played_level(const Header& header, const level::Level& level);

// Re-simulates headless from the seed and checks every recorded state hash.
VerifyResult verify(const Replay& replay, const level::Level& level, const Assets& assets);

}  // namespace bz::game::replay
