#include "game/replay.h"

#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <system_error>

#include "core/error.h"
#include "core/line_reader.h"
#include "core/file_io.h"
#include "core/hash.h"
#include "game/assets.h"
#include "game/difficulty.h"

namespace bz::game::replay {

namespace {

constexpr std::string_view kMagic = "beamzone-replay";

std::string hex(std::uint64_t v) {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
    return buf;
}

// Splits a line into whitespace-separated fields.
std::vector<std::string_view> fields(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

class LineError {
  public:
    LineError(const std::string& name, int line) : name_(name), line_(line) {}
    [[noreturn]] void fail(const std::string& what) const {
        throw UserError(name_ + ":" + std::to_string(line_) + ": error: " + what);
    }
    template <class T>
    T number(std::string_view s, const char* what, int base = 10) const {
        T v{};
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
        if (ec != std::errc() || end != s.data() + s.size()) {
            fail(std::string(what) + " '" + std::string(s) + "' is not a valid number");
        }
        return v;
    }

  private:
    const std::string& name_;
    int line_;
};

}  // namespace

std::string serialise(const Replay& r) {
    std::string out;
    out += std::string(kMagic) + " " + std::to_string(kFormatVersion) + "\n";
    out += "version " + r.header.version + "\n";
    out += "seed " + std::to_string(r.header.seed) + "\n";
    out += "level " + r.header.level + "\n";
    out += "level-hash " + hex(r.header.level_hash) + "\n";
    out += "lives " + std::to_string(r.header.lives) + "\n";
    out += "difficulty " + std::string(difficulty_name(r.header.difficulty)) + "\n";
    out += "hash-interval " + std::to_string(r.header.hash_interval) + "\n";
    out += "ticks " + std::to_string(r.commands.size()) + "\n";
    for (std::size_t i = 0; i < r.commands.size();) {
        std::size_t j = i + 1;
        while (j < r.commands.size() && r.commands[j] == r.commands[i]) ++j;
        const PackedCommand& c = r.commands[i];
        char buf[64];
        std::snprintf(buf, sizeof buf, "c %zu %d %d %02x\n", j - i, c.left, c.right, c.buttons);
        out += buf;
        i = j;
    }
    for (const StateCheck& s : r.checks)
        out += "h " + std::to_string(s.tick) + " " + hex(s.hash) + "\n";
    out += "end\n";
    return out;
}

Replay parse(std::string_view text, const std::string& name) {
    Replay r;
    bool magic = false, have_seed = false, have_level = false, have_hash = false, ended = false;
    std::optional<std::uint64_t> declared_ticks;
    LineReader lines(text);
    std::string_view line;
    while (lines.next(line)) {
        const LineError err(name, lines.line_number());
        const auto f = fields(line);
        if (f.empty() || f[0].front() == '#') continue;
        if (ended) err.fail("text after 'end'");
        const std::string_view key = f[0];
        if (!magic) {
            if (key != kMagic)
                err.fail("not a beamzone replay (expected '" + std::string(kMagic) + " 1')");
            if (f.size() != 2) err.fail("expected '" + std::string(kMagic) + " VERSION'");
            const int v = err.number<int>(f[1], "format version");
            if (v != kFormatVersion) {
                err.fail("replay format " + std::to_string(v) +
                         " is not supported (this build reads " + std::to_string(kFormatVersion) +
                         ")");
            }
            magic = true;
            continue;
        }
        auto want = [&](std::size_t n) {
            if (f.size() != n) {
                err.fail("'" + std::string(key) + "' takes " + std::to_string(n - 1) + " value(s)");
            }
        };
        if (key == "version") {
            want(2);
            r.header.version = std::string(f[1]);
        } else if (key == "seed") {
            want(2);
            r.header.seed = err.number<std::uint64_t>(f[1], "seed");
            have_seed = true;
        } else if (key == "level") {
            // The rest of the line: a path may contain spaces.
            const std::size_t at = line.find("level") + 5;
            std::string_view rest = line.substr(at);
            while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t'))
                rest.remove_prefix(1);
            if (rest.empty()) err.fail("'level' needs a path");
            r.header.level = std::string(rest);
            have_level = true;
        } else if (key == "level-hash") {
            want(2);
            r.header.level_hash = err.number<std::uint64_t>(f[1], "level hash", 16);
            have_hash = true;
        } else if (key == "lives") {
            want(2);
            r.header.lives = err.number<int>(f[1], "lives");
            if (r.header.lives < 1 || r.header.lives > 9) err.fail("lives must be 1..9");
        } else if (key == "difficulty") {
            want(2);
            const auto d = parse_difficulty(f[1]);
            if (!d) {
                err.fail("unknown difficulty '" + std::string(f[1]) + "' (one of " +
                         std::string(kDifficultyNames) + ")");
            }
            r.header.difficulty = *d;
        } else if (key == "hash-interval") {
            want(2);
            r.header.hash_interval = err.number<int>(f[1], "hash interval");
            if (r.header.hash_interval < 1) err.fail("hash-interval must be at least 1");
        } else if (key == "ticks") {
            want(2);
            declared_ticks = err.number<std::uint64_t>(f[1], "tick count");
            if (*declared_ticks > kMaxTicks) {
                err.fail("tick count " + std::to_string(*declared_ticks) +
                         " is over the limit of " + std::to_string(kMaxTicks));
            }
            r.commands.reserve(static_cast<std::size_t>(*declared_ticks));
        } else if (key == "c") {
            want(5);
            if (!declared_ticks) err.fail("'c' before 'ticks'");
            const auto count = err.number<std::uint64_t>(f[1], "run length");
            const int left = err.number<int>(f[2], "left tread");
            const int right = err.number<int>(f[3], "right tread");
            const auto buttons = err.number<unsigned>(f[4], "buttons", 16);
            if (count == 0) err.fail("run length must be at least 1");
            if (left < -127 || left > 127 || right < -127 || right > 127) {
                err.fail("tread values must lie in -127..127");
            }
            if (buttons > 0xff) err.fail("buttons must be two hex digits");
            if (r.commands.size() + count > *declared_ticks) {
                err.fail("more commands than the declared " + std::to_string(*declared_ticks) +
                         " ticks");
            }
            const PackedCommand c{static_cast<std::int8_t>(left), static_cast<std::int8_t>(right),
                                  static_cast<std::uint8_t>(buttons)};
            r.commands.insert(r.commands.end(), static_cast<std::size_t>(count), c);
        } else if (key == "h") {
            want(3);
            StateCheck s;
            s.tick = err.number<std::uint64_t>(f[1], "tick");
            s.hash = err.number<std::uint64_t>(f[2], "state hash", 16);
            if (s.tick == 0) err.fail("state hashes start at tick 1");
            if (!r.checks.empty() && s.tick <= r.checks.back().tick) {
                err.fail("state hash ticks must increase (tick " + std::to_string(s.tick) +
                         " after " + std::to_string(r.checks.back().tick) + ")");
            }
            r.checks.push_back(s);
        } else if (key == "end") {
            want(1);
            ended = true;
        } else {
            err.fail("unknown record '" + std::string(key) + "'");
        }
    }
    const LineError at_end(name, lines.line_number());
    if (!magic) at_end.fail("empty file, not a beamzone replay");
    if (!ended) at_end.fail("the replay is cut short (no 'end' line)");
    if (!have_seed) at_end.fail("missing 'seed'");
    if (!have_level) at_end.fail("missing 'level'");
    if (!have_hash) at_end.fail("missing 'level-hash'");
    if (!declared_ticks) at_end.fail("missing 'ticks'");
    if (r.commands.size() != *declared_ticks) {
        at_end.fail("'ticks' says " + std::to_string(*declared_ticks) + " but the file holds " +
                    std::to_string(r.commands.size()) + " commands");
    }
    if (!r.checks.empty() && r.checks.back().tick > r.commands.size()) {
        at_end.fail("a state hash at tick " + std::to_string(r.checks.back().tick) +
                    " lies past the last tick " + std::to_string(r.commands.size()));
    }
    return r;
}

Replay load(const std::filesystem::path& file) {
    return parse(read_file(file, 256u << 20), file.string());
}

void save(const std::filesystem::path& file, const Replay& replay) {
    write_file_atomic(file, serialise(replay));
}

std::uint64_t level_hash(const level::Level& lv) {
    std::error_code ec;
    if (!lv.file.empty() && std::filesystem::is_regular_file(lv.file, ec)) {
        return hash_bytes(read_file(lv.file));
    }
    Hasher h;
    h.text(lv.name);
    h.value(lv.field_size);
    h.value(lv.wrap);
    h.value(lv.player_start.x);
    h.value(lv.player_start.z);
    h.value(lv.player_heading_deg);
    h.value(lv.obstacles.size());
    for (const level::ObjectDesc& o : lv.obstacles) {
        h.text(o.kind);
        h.text(o.model.string());
        h.value(o.position.x);
        h.value(o.position.y);
        h.value(o.position.z);
        h.value(o.heading_deg);
        h.value(o.scale);
    }
    const level::EnemyRules& e = lv.enemies;
    h.value(e.slow_tank);
    h.value(e.super_tank);
    h.value(e.missile);
    h.value(e.saucer);
    h.value(e.super_tank_score);
    h.value(e.missile_score);
    h.value(e.spawn_min_distance);
    h.value(e.spawn_max_distance);
    h.value(e.aggression);
    h.value(e.saucer_score);
    h.value(e.spawn_rear_chance);
    h.value(e.fire_interval);
    h.value(e.aim_error_deg);
    h.value(e.hold_fire);
    h.value(e.slow_tank_points);
    h.value(e.super_tank_points);
    h.value(e.missile_points);
    h.value(e.saucer_points);
    h.value(static_cast<std::uint8_t>(e.difficulty));
    h.value(lv.player_lives);
    for (const int b : lv.bonus_scores) h.value(b);
    return h.digest();
}

Recorder::Recorder(Header header) {
    replay_.header = std::move(header);
}

void Recorder::record(const TickCommand& command, const World& after) {
    replay_.commands.push_back(pack(command));
    const std::uint64_t tick = after.state().tick;
    if (tick % static_cast<std::uint64_t>(replay_.header.hash_interval) == 0) {
        replay_.checks.push_back({tick, after.state_hash()});
    }
}

Replay Recorder::finish(const World& world) const {
    Replay r = replay_;
    const std::uint64_t tick = world.state().tick;
    if (tick > 0 && (r.checks.empty() || r.checks.back().tick < tick)) {
        r.checks.push_back({tick, world.state_hash()});
    }
    return r;
}

Player::Player(Replay replay) : replay_(std::move(replay)) {}

TickCommand Player::next() {
    if (done()) return TickCommand{};
    return unpack(replay_.commands[next_++]);
}

std::optional<Mismatch> Player::check(const World& world) {
    const std::uint64_t tick = world.state().tick;
    while (next_check_ < replay_.checks.size() && replay_.checks[next_check_].tick < tick)
        ++next_check_;
    if (next_check_ >= replay_.checks.size() || replay_.checks[next_check_].tick != tick)
        return std::nullopt;
    const StateCheck& c = replay_.checks[next_check_++];
    const std::uint64_t actual = world.state_hash();
    if (actual != c.hash) return Mismatch{tick, c.hash, actual};
    ++checks_passed_;
    return std::nullopt;
}

VerifyResult verify(const Replay& replay, const level::Level& level, const Assets& assets) {
    World world(level_for(level, replay.header.difficulty), replay.header.seed, assets.factories(),
                assets.models(), replay.header.lives);
    Player player(replay);
    VerifyResult result;
    while (!player.done()) {
        world.step(player.next());
        ++result.ticks;
        if (auto m = player.check(world)) {
            result.mismatch = m;
            result.checks_passed = player.checks_passed();
            return result;
        }
    }
    result.checks_passed = player.checks_passed();
    result.ok = true;
    return result;
}

}  // namespace bz::game::replay
