#include "platform/free_fly.h"

#include <algorithm>
#include <cmath>

namespace bz::platform {

FreeFlyCamera::FreeFlyCamera(glm::dvec3 position, double yaw_deg, double pitch_deg)
    : position_(position),
      yaw_deg_(yaw_deg),
      pitch_deg_(std::clamp(pitch_deg, -kMaxPitch, kMaxPitch)) {}

glm::dvec3 FreeFlyCamera::forward() const {
    const double yaw = glm::radians(yaw_deg_);
    const double pitch = glm::radians(pitch_deg_);
    return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

void FreeFlyCamera::update(const FlyControls& c, double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) return;
    yaw_deg_ += (c.yaw * kTurnRate * dt) - c.mouse_dx * kMouseDegPerPx;
    pitch_deg_ += (c.pitch * kTurnRate * dt) - c.mouse_dy * kMouseDegPerPx;
    yaw_deg_ = std::fmod(yaw_deg_, 360.0);
    pitch_deg_ = std::clamp(pitch_deg_, -kMaxPitch, kMaxPitch);

    // Moves are level with the ground (forward ignores pitch), as in most level editors.
    const double yaw = glm::radians(yaw_deg_);
    const glm::dvec3 ahead{-std::sin(yaw), 0.0, -std::cos(yaw)};
    const glm::dvec3 right{std::cos(yaw), 0.0, -std::sin(yaw)};
    const double speed = kSpeed * (c.fast ? kFastFactor : 1.0) * dt;
    position_ +=
        speed * (static_cast<double>(c.forward) * ahead + static_cast<double>(c.right) * right +
                 glm::dvec3(0.0, static_cast<double>(c.up), 0.0));
}

}  // namespace bz::platform
