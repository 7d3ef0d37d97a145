#include "game/fixed_step.h"

#include <algorithm>
#include <cmath>

namespace bz::game {

StepPlan FixedStep::advance(double real_dt_seconds) {
    double dt = std::isfinite(real_dt_seconds) ? real_dt_seconds : 0.0;
    dt = std::clamp(dt, 0.0, max_frame_);
    accumulator_ += dt;
    StepPlan plan;
    // A tiny epsilon keeps 1/60 s frames from landing just short of a tick through rounding.
    while (accumulator_ + 1e-9 >= kTickSeconds && plan.ticks < max_ticks_) {
        accumulator_ = std::max(0.0, accumulator_ - kTickSeconds);
        ++plan.ticks;
    }
    if (accumulator_ >= kTickSeconds) accumulator_ = std::fmod(accumulator_, kTickSeconds);
    plan.alpha = std::clamp(accumulator_ / kTickSeconds, 0.0, 1.0);
    return plan;
}

}  // namespace bz::game
