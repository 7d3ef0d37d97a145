#include "app/bench/bench_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "game/assets/backdrop.h"
#include "game/difficulty/autopilot.h"
#include "game/difficulty/difficulty.h"
#include "game/hud/hud.h"

namespace bz::app {

namespace {

// Everything on the level's field, whatever the distance from the player (the benchmark
// camera is not the player's).
constexpr double kWholeField = 1e12;

}  // namespace

std::optional<scene::Camera> camera_on_path(const level::Level& level, double seconds,
                                            double fov_y_deg) {
    const auto& keys = level.camera_path;
    if (keys.empty()) return std::nullopt;
    scene::Camera c;
    c.fov_y_deg = fov_y_deg;
    c.near = 0.3;  // the game's own first-person planes
    c.far = 5000.0;
    const double start = keys.front().time, end = keys.back().time;
    double t = seconds + start;
    if (end > start && t > end) t = start + std::fmod(t - start, end - start);
    std::size_t i = 0;
    while (i + 1 < keys.size() && keys[i + 1].time < t) ++i;
    if (i + 1 >= keys.size() || t <= keys[i].time) {
        const auto& k = t <= keys.front().time ? keys.front() : keys[i];
        c.eye = k.eye;
        c.target = k.target;
        return c;
    }
    const auto& a = keys[i];
    const auto& b = keys[i + 1];
    const double f = (t - a.time) / (b.time - a.time);
    c.eye = a.eye + (b.eye - a.eye) * f;
    c.target = a.target + (b.target - a.target) * f;
    if (glm::length(c.target - c.eye) < 1e-9) c.target = c.eye + glm::dvec3(0.0, 0.0, -1.0);
    return c;
}

BenchScene::BenchScene(level::Level level, std::optional<game::replay::Replay> replay,
                       double fov_y_deg)
    : level_(std::move(level)), assets_(std::make_unique<game::Assets>(level_)), fov_(fov_y_deg) {
    std::uint64_t seed = 1;
    int lives = level_.player_lives;
    level::Difficulty difficulty = level_.enemies.difficulty;
    if (replay) {
        const std::uint64_t want = game::replay::level_hash(level_);
        if (replay->header.level_hash != want) {
            throw UserError("the replay was recorded on a different level (" +
                            replay->header.level + ") than " + level_.file.string());
        }
        seed = replay->header.seed;
        lives = replay->header.lives;
        difficulty = replay->header.difficulty;
        player_.emplace(std::move(*replay));
    }
    world_ = std::make_unique<game::World>(game::level_for(level_, difficulty), seed,
                                           assets_->factories(), assets_->models(), lives);
    try {
        font_ = std::make_unique<scene::VectorFont>(scene::VectorFont::load_default());
    } catch (const UserError&) {
        font_.reset();  // the HUD loses its text, nothing else
    }
}

BenchScene::~BenchScene() = default;

double BenchScene::seconds() const {
    return static_cast<double>(ticks_) * kBenchStep;
}

std::string BenchScene::camera_description() const {
    if (player_) return "replay (" + std::to_string(player_->replay().commands.size()) + " ticks)";
    if (level_.camera_path.empty())
        return "player view driven by the autopilot (the level has no camera path)";
    const double len = level_.camera_path.back().time - level_.camera_path.front().time;
    char buf[96];
    std::snprintf(buf, sizeof buf, "camera path (%zu keys, %.1f s, repeated)",
                  level_.camera_path.size(), len);
    return buf;
}

void BenchScene::prove_replay() {
    if (!player_ || mismatch_) return;
    const auto& checks = player_->replay().checks;
    const std::uint64_t now = world_->state().tick;
    const auto it = std::find_if(checks.begin(), checks.end(),
                                 [now](const game::replay::StateCheck& c) { return c.tick > now; });
    if (it == checks.end()) return;
    while (!player_->done() && world_->state().tick < it->tick) {
        world_->step(player_->next());
        if (const auto m = player_->check(*world_)) {
            mismatch_ = m;
            return;
        }
    }
}

bool BenchScene::next(scene::FrameList& out, double aspect) {
    if (player_) {
        if (player_->done()) return false;
        world_->step(player_->next());
        if (const auto m = player_->check(*world_); m && !mismatch_) mismatch_ = m;
    } else if (level_.camera_path.empty()) {
        world_->step(game::autopilot(*world_));
    } else {
        // The player stands still at the start; the simulation runs on around it.
        world_->step(game::TickCommand{});
    }
    ++ticks_;
    const bool own_view = player_ || level_.camera_path.empty();
    if (own_view) {
        out = world_->interpolated_frame(1.0, fov_);
    } else {
        out = world_->interpolated_frame(1.0, fov_, kWholeField);
        out.camera = *camera_on_path(level_, seconds(), fov_);
    }
    game::backdrop::append_items(out.items, level_.backdrop, assets_->horizon(), out.camera.eye,
                                 seconds());
    game::hud::View view;
    view.aspect = aspect;
    view.fov_y_deg = fov_;
    view.font = font_.get();
    game::hud::play_hud(out.hud, *world_, view);
    return true;
}

}  // namespace bz::app
