// The high-score file (see highscores.h): written whole and atomically; read leniently, so one
// bad line costs that line and never the player's other entries, and a damaged file is moved
// aside rather than overwritten.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <ctime>

#include "core/budgets.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/io/file_io.h"
#include "core/text/line_reader.h"
#include "core/text/printable.h"
#include "game/records/highscores.h"

namespace bz::game {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kHighscoresMagic = "beamzone-highscores";
constexpr int kFormat = 2;
// A few hundred levels' tables; a larger file is not one the game wrote.
constexpr std::size_t kMaxFileBytes = budget::kHighScoreBytes;
constexpr std::size_t kMaxErrors = 100;

class Reader {
  public:
    Reader(std::string_view text, const std::string& name) : lines_(text), name_(name) {}

    HighScoreParse run() {
        std::string_view line;
        while (lines_.next(line)) {
            if (line.empty()) continue;
            if (ended_) {
                error(1, "text after 'end' (ignored from here on)");
                break;
            }
            if (format_ == 0) {
                if (!read_magic(line)) break;  // not our file: nothing in it can be trusted
                continue;
            }
            if (line == "end") {
                ended_ = true;
                continue;
            }
            if (line.starts_with("level")) {
                read_level(line);
            } else {
                read_entry(line);
            }
        }
        if (format_ == 0) {
            if (out_.errors.empty()) error(1, "empty high-score file");
        } else if (!ended_) {
            error(1, "the file is cut short (no 'end' line)");
        }
        flush_table();
        if (dropped_ > 0) {
            out_.errors.back() =
                name_ + ": error: " + std::to_string(dropped_ + 1) + " more errors not shown";
        }
        return std::move(out_);
    }

  private:
    void error(std::size_t column, const std::string& what) {
        if (out_.errors.size() >= kMaxErrors) {
            ++dropped_;
            return;
        }
        out_.errors.push_back(name_ + ":" + std::to_string(std::max(lines_.line_number(), 1)) +
                              ":" + std::to_string(column) + ": error: " + what);
    }

    bool read_magic(std::string_view line) {
        const std::string v1 = std::string(kHighscoresMagic) + " 1";
        const std::string v2 = std::string(kHighscoresMagic) + " " + std::to_string(kFormat);
        if (line == v1) {
            format_ = 1;
            key_ = kSharedTableKey;
            have_key_ = true;
            return true;
        }
        if (line == v2) {
            format_ = kFormat;
            return true;
        }
        error(1, line.starts_with(kHighscoresMagic)
                     ? "high-score format '" + printable(line.substr(kHighscoresMagic.size())) +
                           "' is not one this build reads (1 or 2)"
                     : std::string("not a beamzone high-score file"));
        return false;
    }

    // "level HASH NAME": the name is the rest of the line and may be empty.
    void read_level(std::string_view line) {
        if (format_ == 1) return error(1, "'level' lines belong to format 2 files");
        if (line.size() < 22 || line[5] != ' ' || (line.size() > 22 && line[22] != ' ')) {
            return error(1, "expected 'level', a 16-digit hex rules hash and the level's name");
        }
        const std::string_view digits = line.substr(6, 16);
        std::uint64_t rules = 0;
        const auto [p, ec] =
            std::from_chars(digits.data(), digits.data() + digits.size(), rules, 16);
        if (ec != std::errc() || p != digits.data() + digits.size()) {
            return error(7, "rules hash '" + printable(digits) + "' is not 16 hex digits");
        }
        const std::string_view name = line.size() > 23 ? line.substr(23) : std::string_view();
        const LevelKey key = level_key(name, rules);
        if (key.name != name) {
            return error(24, "level name '" + printable(name) +
                                 "' has characters or a length the game never writes");
        }
        flush_table();
        key_ = key;
        have_key_ = true;
    }

    // "III SCORE": three initials (spaces allowed), one space, digits.
    void read_entry(std::string_view line) {
        if (!have_key_) return error(1, "an entry before the first 'level' line");
        if (line.size() < 5 || line[3] != ' ') {
            return error(
                1, "expected three initials, a space and a score, not '" + printable(line) + "'");
        }
        const std::string_view initials = line.substr(0, 3);
        for (std::size_t i = 0; i < initials.size(); ++i) {
            if (!is_initial(initials[i])) {
                return error(
                    i + 1, "initials must be A-Z, 0-9 or space, not '" + printable(initials) + "'");
            }
        }
        const std::string_view digits = line.substr(4);
        int score = -1;
        const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), score);
        if (ec != std::errc() || p != digits.data() + digits.size() || score <= 0 ||
            score > HighScoreTable::kMaxScore) {
            return error(5, "score '" + printable(digits) + "' is not a number in 1.." +
                                std::to_string(HighScoreTable::kMaxScore));
        }
        if (table_.entries().size() == HighScoreTable::kSize) {
            error(1, "more than " + std::to_string(HighScoreTable::kSize) +
                         " entries for one level (the best ten are kept)");
        }
        table_.insert({std::string(initials), score});
    }

    void flush_table() {
        if (have_key_ && !table_.entries().empty()) out_.book.merge(key_, table_);
        table_ = HighScoreTable();
    }

    LineReader lines_;
    const std::string& name_;
    HighScoreParse out_;
    int format_ = 0;
    bool ended_ = false;
    bool have_key_ = false;
    LevelKey key_;
    HighScoreTable table_;
    std::size_t dropped_ = 0;
};

// "highscores.toml.bad-2026-11-23T14-05-09", with -2, -3, ... if that name is taken.
fs::path aside_name(const fs::path& file) {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H-%M-%S", &utc);
    const std::string base = file.string() + ".bad-" + stamp;
    fs::path p = base;
    std::error_code ec;
    for (int i = 2; fs::exists(fs::symlink_status(p, ec)) && i < 1000; ++i) {
        p = base + "-" + std::to_string(i);
    }
    return p;
}

}  // namespace

std::string serialise(const HighScoreBook& book) {
    std::string out = std::string(kHighscoresMagic) + " " + std::to_string(kFormat) + "\n";
    for (const auto& [key, table] : book.tables()) {
        out += "level " + hex(key.rules) + " " + level_key(key.name, key.rules).name + "\n";
        for (const HighScore& e : table.entries()) {
            out += clean_initials(e.initials) + " " + std::to_string(e.score) + "\n";
        }
    }
    out += "end\n";  // a file cut short (even at a line end) lacks it
    return out;
}

HighScoreParse parse_highscores(std::string_view text, const std::string& name) {
    return Reader(text, name).run();
}

HighScoreLoad load_highscores(const fs::path& file) {
    HighScoreLoad out;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(file, ec))) return out;
    try {
        HighScoreParse parsed =
            parse_highscores(read_file(file, kMaxFileBytes), printable(file.string()));
        out.book = std::move(parsed.book);
        out.errors = std::move(parsed.errors);
    } catch (const UserError& e) {
        out.errors.push_back(e.what());  // unreadable, not a regular file, too large
    }
    if (out.errors.empty()) return out;

    // Damaged: keep the file as it is under another name, then write back what was valid, so
    // neither the player's entries nor the evidence are lost.
    const std::size_t kept = out.book.entry_count();
    const std::string more =
        out.errors.size() > 1 ? " (and " + std::to_string(out.errors.size() - 1) + " more)" : "";
    const fs::path aside = aside_name(file);
    fs::rename(file, aside, ec);
    if (ec) {
        out.may_save = false;
        out.message = "high scores file is damaged: " + out.errors.front() + more +
                      "; it could not be moved aside (" + ec.message() +
                      "), so no high score is saved this run";
        return out;
    }
    out.kept_aside = aside;
    std::string saved;
    if (kept > 0) {
        try {
            save_highscores(file, out.book);
            saved = "; its " + std::to_string(kept) + " valid entries are kept";
        } catch (const UserError& e) {
            saved = "; its " + std::to_string(kept) + " valid entries are kept for this run (" +
                    e.what() + ")";
        }
    } else {
        saved = "; it held no valid entry";
    }
    out.message = "high scores file is damaged: " + out.errors.front() + more + "; kept as " +
                  aside.filename().string() + saved;
    return out;
}

void save_highscores(const fs::path& file, const HighScoreBook& book, const FileWriter& writer) {
    const std::string bytes = serialise(book);
    if (writer) {
        writer(file, bytes);
    } else {
        write_file_atomic(file, bytes);
    }
}

}  // namespace bz::game
