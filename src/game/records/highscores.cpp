#include "game/records/highscores.h"

#include <algorithm>

namespace bz::game {

bool is_initial(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ';
}

std::string clean_initials(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
        if (is_initial(c)) out += c;
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

LevelKey level_key(std::string_view level_name, std::uint64_t rules_hash) {
    // Stored on one line of the file and shown on screen: printable ASCII only, bounded.
    LevelKey key;
    key.rules = rules_hash;
    for (const char c : level_name) {
        if (key.name.size() == kMaxLevelNameBytes) break;
        const bool plain = c >= 0x20 && c < 0x7f;
        key.name += plain ? c : '?';
    }
    while (!key.name.empty() && key.name.back() == ' ') key.name.pop_back();
    return key;
}

HighScoreTable HighScoreBook::table(const LevelKey& key) const {
    for (const auto& [k, t] : tables_) {
        if (k == key) return t;
    }
    return HighScoreTable::defaults();
}

bool HighScoreBook::has(const LevelKey& key) const {
    return std::any_of(tables_.begin(), tables_.end(),
                       [&](const auto& kt) { return kt.first == key; });
}

void HighScoreBook::set(const LevelKey& key, HighScoreTable table) {
    for (auto& [k, t] : tables_) {
        if (k == key) {
            t = std::move(table);
            return;
        }
    }
    tables_.emplace_back(key, std::move(table));
}

void HighScoreBook::merge(const LevelKey& key, const HighScoreTable& table) {
    for (auto& [k, t] : tables_) {
        if (k == key) {
            for (const HighScore& e : table.entries()) t.insert(e);
            return;
        }
    }
    tables_.emplace_back(key, table);
}

std::size_t HighScoreBook::entry_count() const {
    std::size_t n = 0;
    for (const auto& kt : tables_) n += kt.second.entries().size();
    return n;
}

}  // namespace bz::game
