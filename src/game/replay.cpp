#include "game/replay.h"

#include <system_error>

#include "core/file_io.h"
#include "core/hash.h"
#include "game/assets.h"

namespace bz::game::replay {

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
    World world(level, replay.header.seed, assets.factories(), assets.models(),
                replay.header.lives);
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
