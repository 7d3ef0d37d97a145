#pragma once
// The --edit viewer's camera: fly anywhere, look with mouse or arrows. Pure math on glm so it
// is testable; the loop feeds it held keys and mouse motion.
#include <glm/glm.hpp>

namespace bz::platform {

struct FlyControls {
    float forward = 0.0f;   // -1..1 (S..W)
    float right = 0.0f;     // -1..1 (A..D)
    float up = 0.0f;        // -1..1 (F..R, Q..E)
    float yaw = 0.0f;       // -1..1 from keys: + turns left (Left arrow)
    float pitch = 0.0f;     // -1..1 from keys: + looks up (Up arrow)
    float mouse_dx = 0.0f;  // pixels moved since the last update
    float mouse_dy = 0.0f;
    bool fast = false;  // Shift
};

class FreeFlyCamera {
  public:
    FreeFlyCamera(glm::dvec3 position, double yaw_deg, double pitch_deg = 0.0);

    void update(const FlyControls& c, double dt);
    glm::dvec3 position() const { return position_; }
    // Unit view direction. Yaw 0 looks along -z; yaw grows counter-clockwise seen from
    // above (+90 looks along -x), the convention of a heading about +y.
    glm::dvec3 forward() const;
    glm::dvec3 target() const { return position_ + forward(); }
    double yaw_deg() const { return yaw_deg_; }
    double pitch_deg() const { return pitch_deg_; }

    static constexpr double kSpeed = 20.0;  // world units per second
    static constexpr double kFastFactor = 5.0;
    static constexpr double kTurnRate = 90.0;  // degrees per second from keys
    static constexpr double kMouseDegPerPx = 0.15;
    static constexpr double kMaxPitch = 89.0;  // never straight up: keeps `up` valid

  private:
    glm::dvec3 position_;
    double yaw_deg_;
    double pitch_deg_;
};

}  // namespace bz::platform
