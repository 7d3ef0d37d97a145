#pragma once
// Game constants after the 1980 arcade game, in world units (about a metre), seconds and
// ticks of 1/60 s. Changing one changes replays: they are part of the simulation.
namespace bz::game::tuning {

inline constexpr double kDt = 1.0 / 60.0;
inline constexpr int kTicksPerSecond = 60;

// The player's tank.
inline constexpr double kPlayerSpeed = 7.0;     // units/s, both treads full forward
inline constexpr double kPlayerTurnDeg = 50.0;  // deg/s, treads fully opposed
inline constexpr double kPlayerRadius = 1.6;
inline constexpr double kEyeHeight = 1.4;
inline constexpr int kMaxLives = 9;
// Lives, bonus tanks, points, score thresholds, aggression, fire rate and where enemies
// appear are the level's (level::EnemyRules, with the 1980 operator defaults), scaled by the
// difficulty (game/difficulty/difficulty.h).

// Shells. One player shell may be in flight at a time.
inline constexpr double kShellSpeed = 45.0;
inline constexpr double kShellRange = 110.0;
inline constexpr double kEnemyShellSpeed = 34.0;
inline constexpr double kEnemyShellRange = 90.0;
inline constexpr double kShellRadius = 0.3;
inline constexpr double kShellHeight = 1.0;
inline constexpr double kMuzzleOffset = 2.4;  // ahead of the tank's centre

// Enemy tanks.
inline constexpr double kTankSpeed = 4.5;
inline constexpr double kTankTurnDeg = 40.0;
inline constexpr double kSuperTankSpeed = 9.0;  // twice the slow tank
inline constexpr double kSuperTankTurnDeg = 80.0;
inline constexpr double kTankRadius = 1.8;
inline constexpr double kTankHeight = 1.6;
inline constexpr double kEngageDistance = 55.0;  // starts aiming and firing from here
inline constexpr double kAimToleranceDeg = 2.5;  // fires when its gun points this close

// How an enemy tank hunts (game/world/world_enemies.cpp). A slow tank is this much less
// aggressive than the level's aggression says; a super tank is as aggressive.
inline constexpr double kSlowTankAggression = 0.8;
// Approach: come in at up to this angle off the direct line, straightening up from this distance
// in, for a random stretch of these many ticks.
inline constexpr double kApproachOffsetDeg = 40.0;
inline constexpr double kApproachStraightenDistance = 80.0;
inline constexpr int kApproachMinTicks = 120;
inline constexpr int kApproachMaxTicks = 300;
// Attack: hold off at shooting range rather than close in (a shell from afar can miss): half
// speed beyond kHoldOffFar, still between the two, backing off inside kHoldOffNear. Beyond
// kEngageDistance times kDisengageFactor the tank approaches again.
inline constexpr int kAttackMinTicks = 180;
inline constexpr int kAttackMaxTicks = 420;
inline constexpr double kHoldOffFar = 40.0;
inline constexpr double kHoldOffNear = 20.0;
inline constexpr double kHoldOffFarThrottle = 0.5;
inline constexpr double kHoldOffNearThrottle = -0.4;
inline constexpr double kDisengageFactor = 1.4;
// At the end of an attack stretch a tank evades (turns this far off the player) with chance
// 1 - kEvadeAggressionWeight * aggression, else it attacks on.
inline constexpr double kEvadeAggressionWeight = 0.6;
inline constexpr double kEvadeTurnDeg = 100.0;
inline constexpr int kEvadeMinTicks = 60;
inline constexpr int kEvadeMaxTicks = 150;
// A careful tank dodges (turns this far) when the player's gun is within kDodgeAimDeg of it,
// with this chance per tick at aggression 0 (none at 1).
inline constexpr double kDodgeAimDeg = 3.0;
inline constexpr double kDodgeChancePerTick = 0.015;
inline constexpr double kDodgeTurnDeg = 90.0;
inline constexpr int kDodgeMinTicks = 50;
inline constexpr int kDodgeMaxTicks = 100;
// Blocked by an obstacle, a tank detours this far off its heading for a while.
inline constexpr double kDetourTurnDeg = 90.0;
inline constexpr int kDetourMinTicks = 40;
inline constexpr int kDetourMaxTicks = 90;
// It turns on the spot while its goal lies further than this off its nose.
inline constexpr double kTurnOnTheSpotDeg = 60.0;
// Reload after a shot: the level's fire interval times (kReloadBase + kReloadCalm * calm),
// calm = 1 - aggression, plus up to a second at random.
inline constexpr double kReloadBase = 0.75;
inline constexpr double kReloadCalm = 0.5;

// The guided missile.
inline constexpr double kMissileSpeed = 16.0;
inline constexpr double kMissileTurnDeg = 150.0;
inline constexpr double kMissileRadius = 1.2;
inline constexpr double kMissileCruise = 0.8;     // altitude of its base over open ground
inline constexpr double kMissileClimb = 12.0;     // vertical speed, units/s
inline constexpr double kMissileLookAhead = 9.0;  // looks this far ahead for obstacles to hop
inline constexpr double kMissileWeaveDeg = 40.0;  // zig-zag amplitude
inline constexpr double kMissileWeaveHz = 0.9;
inline constexpr double kMissileStraightDistance = 14.0;  // stops weaving this close
// Nastier, from level::EnemyRules::missile_nastier_after points past the missile score (the
// arcade's 25,000: missile_nastier_delta in stephenlclarke/battlezone's ROM-derived
// assets/arcade/arcade-rules.txt). The sources say when, not how; that remake narrows and
// quickens the missile's sway, which here made it easier (the autopilot shot down 60 of 60
// such missiles, against 45 of 60 before; narrower or quicker weaves alone did the same). So
// here it flies a quarter faster and turns half as sharply again, on the same weave: the
// autopilot then shoots down 35 of 60 and is hit by 25 (WorldMotion test).
inline constexpr double kMissileNastySpeed = kMissileSpeed * 1.25;
inline constexpr double kMissileNastyTurnDeg = kMissileTurnDeg * 1.5;

// The flying saucer: harmless, not on radar.
inline constexpr double kSaucerSpeed = 5.0;
inline constexpr double kSaucerRadius = 1.8;
inline constexpr double kSaucerAltitude = 0.6;
inline constexpr int kSaucerLifeTicks = 20 * kTicksPerSecond;
inline constexpr int kSaucerMinDelayTicks = 25 * kTicksPerSecond;
inline constexpr int kSaucerMaxDelayTicks = 50 * kTicksPerSecond;

// Pacing.
inline constexpr int kFirstSpawnTicks = 90;
inline constexpr int kRespawnTicks = 150;
inline constexpr int kDyingTicks = 180;  // the cracked screen before the next tank
inline constexpr int kBlockedMessageTicks = 45;

// Debris.
inline constexpr double kGravity = 14.0;
inline constexpr int kDebrisTicks = 4 * kTicksPerSecond;

// What the tank's crew sees: enemies outside this half-angle are "to left/right/rear".
inline constexpr double kViewHalfAngleDeg = 30.0;
inline constexpr double kRearAngleDeg = 135.0;
inline constexpr double kRadarSweepSeconds = 2.0;

}  // namespace bz::game::tuning
