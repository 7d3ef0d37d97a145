// libFuzzer target: any bytes through the high-score reader give a book of valid tables and
// at most 100 positioned, printable messages; what it keeps serialises and reads back the same.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_checks.h"
#include "game/records/highscores.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    using namespace bz::game;
    const HighScoreParse r = parse_highscores(text, "hs.toml");
    if (r.errors.size() > 100) __builtin_trap();
    for (const std::string& e : r.errors) bz::fuzz::check_message(e, "hs.toml:", false);
    for (const auto& [key, table] : r.book.tables()) {
        if (table.entries().empty() || table.entries().size() > HighScoreTable::kSize)
            __builtin_trap();
        if (key.name.size() > kMaxLevelNameBytes) __builtin_trap();
        for (std::size_t i = 1; i < table.entries().size(); ++i) {
            if (table.entries()[i - 1].score < table.entries()[i].score) __builtin_trap();
        }
    }
    const HighScoreParse again = parse_highscores(serialise(r.book), "again");
    if (!again.errors.empty() || !(again.book == r.book)) __builtin_trap();
    return 0;
}
