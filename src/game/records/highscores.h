#pragma once
// High-score tables, one per level: ten entries of three initials and a score, best first.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bz::game {

struct HighScore {
    std::string initials;  // 3 characters A-Z, 0-9 or space
    int score = 0;
    bool operator==(const HighScore&) const = default;
};

class HighScoreTable {
  public:
    static constexpr std::size_t kSize = 10;
    static constexpr std::size_t kInitials = 3;
    static constexpr int kMaxScore = 99'999'999;

    // The table a fresh install starts with.
    static HighScoreTable defaults();

    const std::vector<HighScore>& entries() const { return entries_; }
    int best() const { return entries_.empty() ? 0 : entries_.front().score; }
    // Would `score` earn a place?
    bool qualifies(int score) const;
    // Inserts in order (after equal scores, so older entries keep their place); returns the
    // rank (0 = best), or nullopt when it did not make the table.
    std::optional<std::size_t> insert(HighScore entry);

    bool operator==(const HighScoreTable&) const = default;

  private:
    std::vector<HighScore> entries_;
};

// Which level a table belongs to: the level's name and a hash of its rules (level_rules.h),
// so an easy custom level never shares a table with the classic one, and a level whose rules
// were edited starts a fresh table.
struct LevelKey {
    std::string name;  // as the file stores it: printable, at most kMaxLevelNameBytes
    std::uint64_t rules = 0;
    bool operator==(const LevelKey&) const = default;
};
inline constexpr std::size_t kMaxLevelNameBytes = 64;
LevelKey level_key(std::string_view level_name, std::uint64_t rules_hash);
// Files of format 1 held one table that every level shared; it is kept under this key.
inline const LevelKey kSharedTableKey{"", 0};

// Every level's table, in the order first seen.
class HighScoreBook {
  public:
    // The level's table, or the defaults when it has none yet.
    HighScoreTable table(const LevelKey& key) const;
    bool has(const LevelKey& key) const;
    void set(const LevelKey& key, HighScoreTable table);
    // Adds each entry of `table` to the level's table (as a file with a level twice reads).
    void merge(const LevelKey& key, const HighScoreTable& table);
    const std::vector<std::pair<LevelKey, HighScoreTable>>& tables() const { return tables_; }
    std::size_t entry_count() const;
    bool operator==(const HighScoreBook&) const = default;

  private:
    std::vector<std::pair<LevelKey, HighScoreTable>> tables_;
};

// File format 2 (text; format 1 is format 2 with one unnamed table and no 'level' lines):
//   beamzone-highscores 2
//   level 0123456789abcdef Classic      the rules hash (hex) and the level's name
//   ABC 125000                          up to ten entries, best first
//   ...
//   end                                 absent = the file was cut short
std::string serialise(const HighScoreBook& book);

struct HighScoreParse {
    HighScoreBook book;               // every valid entry, whatever else was wrong
    std::vector<std::string> errors;  // "NAME:LINE:COL: error: ...", at most 100
};
// Never throws: a bad line is reported and skipped, and the rest of the file still counts.
HighScoreParse parse_highscores(std::string_view text, const std::string& name);

struct HighScoreLoad {
    HighScoreBook book;
    std::vector<std::string> errors;  // what was wrong with the file; empty when it was fine
    // A damaged file is moved aside (highscores.toml.bad-DATE) and its valid entries are
    // written back at once; this names where it went (empty when nothing was moved).
    std::filesystem::path kept_aside;
    // False when a damaged file could not be moved aside: it must then never be overwritten.
    bool may_save = true;
    // One line for the screen and the log, empty when all was well.
    std::string message;
};
// A missing file gives an empty book silently. Never throws for bad content.
HighScoreLoad load_highscores(const std::filesystem::path& file);

// How a file gets written; the default is bz::write_file_atomic (temp file, fsync, rename).
using FileWriter = std::function<void(const std::filesystem::path&, std::string_view)>;
// Throws UserError when the write fails; the previous file is untouched then.
void save_highscores(const std::filesystem::path& file, const HighScoreBook& book,
                     const FileWriter& writer = {});

// A character initials may hold: A-Z, 0-9 or space.
bool is_initial(char c);
// Upper-cases and keeps only A-Z, 0-9 and space, padded or cut to three characters.
std::string clean_initials(std::string_view text);

}  // namespace bz::game
