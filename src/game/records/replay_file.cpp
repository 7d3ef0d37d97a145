// The replay file format (see replay.h): writing it, and reading it back from untrusted bytes.
// Every count is checked against what the file declared before anything is allocated, and
// every message names the file, line and column, with the offending text escaped and cut.
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <system_error>
#include <utility>

#include "core/budgets.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/io/file_io.h"
#include "core/text/line_reader.h"
#include "core/text/printable.h"
#include "game/difficulty/difficulty.h"
#include "game/records/replay.h"

namespace bz::game::replay {

namespace {

constexpr std::string_view kReplayMagic = "beamzone-replay";
// A build version such as "0.1.0-dirty" and a level path: generous, but bounded, so a
// hostile file cannot make every later message carry megabytes.
constexpr std::size_t kMaxVersionBytes = 64;
constexpr std::size_t kMaxLevelPathBytes = 4096;
// A replay of kMaxTicks with a new command every tick is about 20 bytes a line.
constexpr std::size_t kMaxReplayBytes = budget::kReplayBytes;

// Splits a line into whitespace-separated fields (views into the line, so a field's column
// is its offset).
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

bool has_control_character(std::string_view s) {
    for (const char c : s) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return true;
    }
    return false;
}

// Reports errors at NAME:LINE:COL, the column of the field (or text) at fault.
class LineError {
  public:
    LineError(const std::string& name, int line, std::string_view text)
        : name_(name), line_(std::max(line, 1)), text_(text) {}
    [[noreturn]] void fail(const std::string& what) const { fail_column(1, what); }
    [[noreturn]] void fail_at(std::string_view part, const std::string& what) const {
        std::size_t column = 1;
        if (part.data() >= text_.data() && part.data() <= text_.data() + text_.size()) {
            column = static_cast<std::size_t>(part.data() - text_.data()) + 1;
        }
        fail_column(column, what);
    }
    template <class T>
    T number(std::string_view s, const char* what, int base = 10) const {
        T v{};
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, base);
        if (ec != std::errc() || end != s.data() + s.size()) {
            fail_at(s, std::string(what) + " '" + printable(s) + "' is not a valid number" +
                           (ec == std::errc::result_out_of_range ? " in range" : ""));
        }
        return v;
    }

  private:
    [[noreturn]] void fail_column(std::size_t column, const std::string& what) const {
        throw UserError(name_ + ":" + std::to_string(line_) + ":" + std::to_string(column) +
                        ": error: " + what);
    }
    const std::string& name_;
    int line_;
    std::string_view text_;
};

// A free-text value (version, level path): bounded and free of control characters.
std::string text_value(const LineError& err, std::string_view value, std::size_t max_bytes,
                       const char* what) {
    if (value.size() > max_bytes) {
        err.fail_at(value, std::string(what) + " is " + std::to_string(value.size()) +
                               " bytes long, over the limit of " + std::to_string(max_bytes));
    }
    if (has_control_character(value)) {
        err.fail_at(value,
                    std::string(what) + " '" + printable(value) + "' holds a control character");
    }
    return std::string(value);
}

// A rule's score (missiles from, the first bonus tank): the high-score table's largest.
constexpr int kMaxRuleScore = 99'999'999;

using Fields = std::vector<std::string_view>;

// Reads a replay line by line: the magic line first, then header fields, command runs and
// state hashes in any order, then 'end'; at the end, checks that nothing is missing.
class Reader {
  public:
    explicit Reader(const std::string& name) : name_(name) {
        r_.header.missile_nastier_after = 0;  // absent: recorded before the rule existed
    }

    Replay read(std::string_view text) {
        LineReader lines(text);
        std::string_view line;
        while (lines.next(line)) {
            const LineError err(name_, lines.line_number(), line);
            const Fields f = fields(line);
            if (f.empty() || f[0].front() == '#') continue;
            if (ended_) err.fail_at(f[0], "text after 'end'");
            if (!magic_) {
                read_magic(err, f);
            } else {
                read_record(err, line, f);
            }
        }
        check_complete(LineError(name_, lines.line_number(), {}));
        return std::move(r_);
    }

  private:
    void read_magic(const LineError& err, const Fields& f) {
        const std::string_view key = f[0];
        if (key != kReplayMagic)
            err.fail_at(key,
                        "not a beamzone replay (expected '" + std::string(kReplayMagic) + " 1')");
        if (f.size() != 2) err.fail_at(key, "expected '" + std::string(kReplayMagic) + " VERSION'");
        const int v = err.number<int>(f[1], "format version");
        if (v != kFormatVersion) {
            err.fail_at(f[1], "replay format " + std::to_string(v) +
                                  " is not supported (this build reads " +
                                  std::to_string(kFormatVersion) + ")");
        }
        magic_ = true;
    }

    // The record's name (f[0]) with exactly n - 1 values after it.
    static void want(const LineError& err, const Fields& f, std::size_t n) {
        if (f.size() != n) {
            err.fail_at(f[0],
                        "'" + std::string(f[0]) + "' takes " + std::to_string(n - 1) + " value(s)");
        }
    }

    void read_record(const LineError& err, std::string_view line, const Fields& f) {
        const std::string_view key = f[0];
        if (key == "level") {
            read_level(err, line, key);
        } else if (key == "ticks") {
            read_ticks(err, f);
        } else if (key == "c") {
            read_run(err, f);
        } else if (key == "h") {
            read_state_check(err, f);
        } else if (key == "end") {
            want(err, f, 1);
            ended_ = true;
        } else {
            read_header_value(err, f);
        }
    }

    // The one-value header fields.
    void read_header_value(const LineError& err, const Fields& f) {
        const std::string_view key = f[0];
        Header& h = r_.header;
        if (key == "version") {
            want(err, f, 2);
            h.version = text_value(err, f[1], kMaxVersionBytes, "the version");
        } else if (key == "seed") {
            want(err, f, 2);
            h.seed = err.number<std::uint64_t>(f[1], "seed");
            have_seed_ = true;
        } else if (key == "level-hash") {
            want(err, f, 2);
            h.level_hash = err.number<std::uint64_t>(f[1], "level hash", 16);
            have_hash_ = true;
        } else if (key == "lives") {
            want(err, f, 2);
            h.lives = err.number<int>(f[1], "lives");
            if (h.lives < 1 || h.lives > 9) err.fail_at(f[1], "lives must be 1..9");
        } else if (key == "difficulty") {
            want(err, f, 2);
            const auto d = parse_difficulty(f[1]);
            if (!d) {
                err.fail_at(f[1], "unknown difficulty '" + printable(f[1]) + "' (one of " +
                                      std::string(kDifficultyNames) + ")");
            }
            h.difficulty = *d;
        } else if (key == "missile-score" || key == "bonus-score") {
            want(err, f, 2);
            const int v = err.number<int>(f[1], "score");
            if (v < 0 || v > kMaxRuleScore) {
                err.fail_at(f[1],
                            std::string(key) + " must be 0.." + std::to_string(kMaxRuleScore));
            }
            (key == "missile-score" ? h.missile_score : h.bonus_score) = v;
        } else if (key == "missile-nastier-after") {
            want(err, f, 2);
            const int v = err.number<int>(f[1], "score");
            if (v < 0 || v > kMaxRuleScore) {
                err.fail_at(f[1],
                            "missile-nastier-after must be 0.." + std::to_string(kMaxRuleScore));
            }
            h.missile_nastier_after = v;
        } else if (key == "hash-interval") {
            want(err, f, 2);
            h.hash_interval = err.number<int>(f[1], "hash interval");
            if (h.hash_interval < 1) err.fail_at(f[1], "hash-interval must be at least 1");
        } else {
            err.fail_at(key, "unknown record '" + printable(key) + "'");
        }
    }

    // The rest of the line: a path may contain spaces.
    void read_level(const LineError& err, std::string_view line, std::string_view key) {
        std::string_view rest =
            line.substr(static_cast<std::size_t>(key.data() - line.data()) + key.size());
        while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t'))
            rest.remove_prefix(1);
        if (rest.empty()) err.fail_at(key, "'level' needs a path");
        r_.header.level = text_value(err, rest, kMaxLevelPathBytes, "the level path");
        have_level_ = true;
    }

    void read_ticks(const LineError& err, const Fields& f) {
        want(err, f, 2);
        if (declared_ticks_) err.fail_at(f[0], "'ticks' given twice");
        declared_ticks_ = err.number<std::uint64_t>(f[1], "tick count");
        if (*declared_ticks_ > kMaxTicks) {
            err.fail_at(f[1], "tick count " + std::to_string(*declared_ticks_) +
                                  " is over the limit of " + std::to_string(kMaxTicks));
        }
        r_.commands.reserve(static_cast<std::size_t>(*declared_ticks_));
    }

    // 'c COUNT LEFT RIGHT BUTTONS': the same command for COUNT ticks.
    void read_run(const LineError& err, const Fields& f) {
        want(err, f, 5);
        if (!declared_ticks_) err.fail_at(f[0], "'c' before 'ticks'");
        const auto count = err.number<std::uint64_t>(f[1], "run length");
        const int left = err.number<int>(f[2], "left tread");
        const int right = err.number<int>(f[3], "right tread");
        const auto buttons = err.number<unsigned>(f[4], "buttons", 16);
        if (count == 0) err.fail_at(f[1], "run length must be at least 1");
        if (left < -127 || left > 127) err.fail_at(f[2], "tread values must lie in -127..127");
        if (right < -127 || right > 127) err.fail_at(f[3], "tread values must lie in -127..127");
        if (buttons > 0xff) err.fail_at(f[4], "buttons must be two hex digits");
        // Compared as what is left, so a count near 2^64 cannot wrap the sum around.
        const std::uint64_t room = *declared_ticks_ - r_.commands.size();
        if (count > room) {
            err.fail_at(f[1], "run length " + std::to_string(count) +
                                  " makes more commands than the declared " +
                                  std::to_string(*declared_ticks_) + " ticks (" +
                                  std::to_string(room) + " left)");
        }
        const PackedCommand c{static_cast<std::int8_t>(left), static_cast<std::int8_t>(right),
                              static_cast<std::uint8_t>(buttons)};
        r_.commands.insert(r_.commands.end(), static_cast<std::size_t>(count), c);
    }

    // 'h TICK HASH': the state hash after TICK.
    void read_state_check(const LineError& err, const Fields& f) {
        want(err, f, 3);
        if (!declared_ticks_) err.fail_at(f[0], "'h' before 'ticks'");
        StateCheck s;
        s.tick = err.number<std::uint64_t>(f[1], "tick");
        s.hash = err.number<std::uint64_t>(f[2], "state hash", 16);
        if (s.tick == 0) err.fail_at(f[1], "state hashes start at tick 1");
        // Checked here, not only at the end: it also bounds how many hashes are kept.
        if (s.tick > *declared_ticks_) {
            err.fail_at(f[1], "a state hash at tick " + std::to_string(s.tick) +
                                  " lies past the declared " + std::to_string(*declared_ticks_) +
                                  " ticks");
        }
        if (!r_.checks.empty() && s.tick <= r_.checks.back().tick) {
            err.fail_at(f[1], "state hash ticks must increase (tick " + std::to_string(s.tick) +
                                  " after " + std::to_string(r_.checks.back().tick) + ")");
        }
        r_.checks.push_back(s);
    }

    void check_complete(const LineError& at_end) const {
        if (!magic_) at_end.fail("empty file, not a beamzone replay");
        if (!ended_) at_end.fail("the replay is cut short (no 'end' line)");
        if (!have_seed_) at_end.fail("missing 'seed'");
        if (!have_level_) at_end.fail("missing 'level'");
        if (!have_hash_) at_end.fail("missing 'level-hash'");
        if (!declared_ticks_) at_end.fail("missing 'ticks'");
        if (r_.commands.size() != *declared_ticks_) {
            at_end.fail("'ticks' says " + std::to_string(*declared_ticks_) +
                        " but the file holds " + std::to_string(r_.commands.size()) + " commands");
        }
    }

    const std::string& name_;
    Replay r_;
    bool magic_ = false, have_seed_ = false, have_level_ = false, have_hash_ = false;
    bool ended_ = false;
    std::optional<std::uint64_t> declared_ticks_;
};

}  // namespace

std::string serialise(const Replay& r) {
    std::string out;
    out += std::string(kReplayMagic) + " " + std::to_string(kFormatVersion) + "\n";
    out += "version " + r.header.version + "\n";
    out += "seed " + std::to_string(r.header.seed) + "\n";
    out += "level " + r.header.level + "\n";
    out += "level-hash " + hex(r.header.level_hash) + "\n";
    out += "lives " + std::to_string(r.header.lives) + "\n";
    out += "difficulty " + std::string(difficulty_name(r.header.difficulty)) + "\n";
    if (r.header.missile_score) {
        out += "missile-score " + std::to_string(*r.header.missile_score) + "\n";
    }
    if (r.header.bonus_score) out += "bonus-score " + std::to_string(*r.header.bonus_score) + "\n";
    if (r.header.missile_nastier_after != 0) {
        out += "missile-nastier-after " + std::to_string(r.header.missile_nastier_after) + "\n";
    }
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
    return Reader(name).read(text);
}

Replay load(const std::filesystem::path& file) {
    return parse(read_file(file, kMaxReplayBytes), printable(file.string()));
}

void save(const std::filesystem::path& file, const Replay& replay) {
    write_file_atomic(file, serialise(replay));
}

}  // namespace bz::game::replay
