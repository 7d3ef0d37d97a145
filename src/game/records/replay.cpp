#include "game/records/replay.h"

#include <algorithm>
#include <system_error>

#include "core/hash.h"
#include "core/io/file_io.h"
#include "game/assets/assets.h"
#include "game/difficulty/arcade_rules.h"
#include "game/difficulty/difficulty.h"
#include "game/records/level_rules.h"

namespace bz::game::replay {

std::uint64_t level_hash(const level::Level& lv) {
    std::error_code ec;
    if (!lv.file.empty() && std::filesystem::is_regular_file(lv.file, ec)) {
        return hash_bytes(read_file(lv.file));
    }
    // The built-in level has no file: its name and rules stand for it.
    Hasher h;
    h.text(lv.name);
    h.value(level_rules_hash(lv));
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

std::string missing_state_hashes(const Replay& replay) {
    const std::uint64_t ticks = replay.commands.size();
    if (ticks == 0) return "it holds no ticks";
    if (replay.checks.empty()) return "it holds no state hashes";
    const auto interval = static_cast<std::uint64_t>(std::max(1, replay.header.hash_interval));
    std::size_t k = 0;
    auto has = [&](std::uint64_t tick) {
        while (k < replay.checks.size() && replay.checks[k].tick < tick) ++k;
        return k < replay.checks.size() && replay.checks[k].tick == tick;
    };
    for (std::uint64_t t = interval; t <= ticks; t += interval) {
        if (!has(t)) {
            return "it has no state hash at tick " + std::to_string(t) + " (one every " +
                   std::to_string(interval) + " ticks is recorded)";
        }
    }
    if (!has(ticks)) return "it has no state hash at its last tick, " + std::to_string(ticks);
    if (replay.checks.back().tick > ticks) {
        return "it has a state hash at tick " + std::to_string(replay.checks.back().tick) +
               ", after its last tick " + std::to_string(ticks);
    }
    return {};
}

level::Level played_level(const Header& header, const level::Level& level) {
    ArcadeRules recorded;  // lives come from the header's own line
    recorded.missile_score = header.missile_score;
    recorded.bonus_score = header.bonus_score;
    level::Level playing = with_arcade_rules(level_for(level, header.difficulty), recorded);
    playing.enemies.missile_nastier_after = header.missile_nastier_after;
    return playing;
}

VerifyResult verify(const Replay& replay, const level::Level& level, const Assets& assets) {
    World world(played_level(replay.header, level), replay.header.seed, assets.factories(),
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
