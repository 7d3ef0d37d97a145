#pragma once
// The high-score table: ten entries of three initials and a score, best first.
//
// File format (text):
//   beamzone-highscores 1
//   ABC 125000
//   ...
//   end          (absent = the file was cut short)
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
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

std::string serialise(const HighScoreTable& table);
// Throws UserError "NAME:LINE: error: ..." on anything malformed.
HighScoreTable parse_highscores(std::string_view text, const std::string& name);

struct HighScoreLoad {
    HighScoreTable table;
    std::string warning;  // empty, or why the file was ignored (the defaults are used then)
};
// A missing file gives the defaults silently; a corrupt or partial one gives the defaults and
// a one-line warning. Never throws for bad content.
HighScoreLoad load_highscores(const std::filesystem::path& file);

// How a file gets written; the default is bz::write_file_atomic (temp file, fsync, rename).
using FileWriter = std::function<void(const std::filesystem::path&, std::string_view)>;
// Throws UserError when the write fails; the previous file is untouched then.
void save_highscores(const std::filesystem::path& file, const HighScoreTable& table,
                     const FileWriter& writer = {});

// Upper-cases and keeps only A-Z, 0-9 and space, padded or cut to three characters.
std::string clean_initials(std::string_view text);

}  // namespace bz::game
