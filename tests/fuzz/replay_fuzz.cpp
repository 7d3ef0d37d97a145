// libFuzzer target: any bytes through the replay parser must give either a replay that
// serialises back to something that parses the same, or one file:line:col message without
// control characters; never a crash, a sanitizer report, an unbounded allocation or a hang.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "fuzz_checks.h"
#include "game/records/replay.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    namespace replay = bz::game::replay;
    try {
        const replay::Replay r = replay::parse(text, "f.replay");
        if (r.commands.size() > replay::kMaxTicks) __builtin_trap();
        // What the parser accepts, the writer writes back in a form it accepts again.
        const replay::Replay again = replay::parse(replay::serialise(r), "again.replay");
        if (again.commands != r.commands || again.checks.size() != r.checks.size() ||
            again.header.level != r.header.level || again.header.seed != r.header.seed) {
            __builtin_trap();
        }
    } catch (const bz::UserError& e) {
        bz::fuzz::check_message(e.what(), "f.replay:", true);
    }
    return 0;
}
