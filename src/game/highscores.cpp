#include "game/highscores.h"

#include <algorithm>
#include <charconv>

#include "core/error.h"
#include "core/line_reader.h"
#include "core/file_io.h"

namespace bz::game {

namespace {

constexpr std::string_view kMagic = "beamzone-highscores";
constexpr int kMaxScore = 99'999'999;

bool valid_initial(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ';
}

}  // namespace

std::string clean_initials(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
        if (valid_initial(c)) out += c;
        if (out.size() == HighScoreTable::kInitials) break;
    }
    out.resize(HighScoreTable::kInitials, ' ');
    return out;
}

HighScoreTable HighScoreTable::defaults() {
    HighScoreTable t;
    const char* names[] = {"EDR", "JED", "MAR", "BZN", "TNK", "RAD", "VEC", "GRN", "ATR", "ARC"};
    int score = 100000;
    for (const char* n : names) {
        t.entries_.push_back({n, score});
        score = score > 20000 ? score - 15000 : score - 2000;
    }
    return t;
}

bool HighScoreTable::qualifies(int score) const {
    if (score <= 0) return false;
    return entries_.size() < kSize || score > entries_.back().score;
}

std::optional<std::size_t> HighScoreTable::insert(HighScore entry) {
    if (!qualifies(entry.score)) return std::nullopt;
    entry.initials = clean_initials(entry.initials);
    entry.score = std::min(entry.score, kMaxScore);
    const auto at = std::upper_bound(entries_.begin(), entries_.end(), entry.score,
                                     [](int s, const HighScore& e) { return s > e.score; });
    const auto rank = static_cast<std::size_t>(at - entries_.begin());
    entries_.insert(at, entry);
    if (entries_.size() > kSize) entries_.resize(kSize);
    return rank;
}

std::string serialise(const HighScoreTable& table) {
    std::string out = std::string(kMagic) + " 1\n";
    for (const HighScore& e : table.entries()) {
        out += clean_initials(e.initials) + " " + std::to_string(e.score) + "\n";
    }
    out += "end\n";  // a file cut short (even at a line end) lacks it
    return out;
}

HighScoreTable parse_highscores(std::string_view text, const std::string& name) {
    HighScoreTable t;
    std::vector<HighScore> read;
    bool magic = false;
    bool ended = false;
    LineReader lines(text);
    auto fail = [&](const std::string& what) -> void {
        throw UserError(name + ":" + std::to_string(lines.line_number()) + ": error: " + what);
    };
    std::string_view line;
    while (lines.next(line)) {
        if (line.empty()) continue;
        if (!magic) {
            if (line != std::string(kMagic) + " 1") fail("not a beamzone high-score file");
            magic = true;
            continue;
        }
        if (ended) fail("text after 'end'");
        if (line == "end") {
            ended = true;
            continue;
        }
        // "III SCORE": three initials (spaces allowed), one space, digits.
        if (line.size() < 5 || line[3] != ' ') fail("expected three initials, a space and a score");
        const std::string_view initials = line.substr(0, 3);
        if (!std::all_of(initials.begin(), initials.end(), valid_initial)) {
            fail("initials must be A-Z, 0-9 or space");
        }
        const std::string_view digits = line.substr(4);
        int score = -1;
        const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), score);
        if (ec != std::errc() || p != digits.data() + digits.size() || score < 0 ||
            score > kMaxScore) {
            fail("score '" + std::string(digits) + "' is not a number in 0.." +
                 std::to_string(kMaxScore));
        }
        if (read.size() == HighScoreTable::kSize) fail("more than 10 entries");
        if (!read.empty() && score > read.back().score) fail("entries are not sorted best first");
        read.push_back({std::string(initials), score});
    }
    if (!magic) fail("empty high-score file");
    if (!ended) fail("the file is cut short (no 'end' line)");
    for (HighScore& e : read) {
        if (!t.insert(e)) {
            // A zero score never qualifies; keep the file's entry anyway for a faithful load.
            fail("score must be above 0");
        }
    }
    return t;
}

HighScoreLoad load_highscores(const std::filesystem::path& file) {
    HighScoreLoad out{HighScoreTable::defaults(), {}};
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return out;
    try {
        out.table = parse_highscores(read_file(file, 64u << 10), file.string());
    } catch (const UserError& e) {
        out.table = HighScoreTable::defaults();
        out.warning = std::string(e.what()) + " (using the default high scores)";
    }
    return out;
}

void save_highscores(const std::filesystem::path& file, const HighScoreTable& table,
                     const FileWriter& writer) {
    const std::string bytes = serialise(table);
    if (writer) {
        writer(file, bytes);
    } else {
        write_file_atomic(file, bytes);
    }
}

}  // namespace bz::game
