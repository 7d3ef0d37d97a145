#pragma once
// Turns variable frame times into a whole number of fixed simulation ticks plus the fraction
// left over, which the renderer uses to interpolate between the last two states.
namespace bz::game {

struct StepPlan {
    int ticks = 0;       // simulation ticks to run this frame
    double alpha = 0.0;  // 0..1: how far the display lies between the previous and current state
};

class FixedStep {
  public:
    static constexpr double kTickSeconds = 1.0 / 60.0;

    // max_frame: longer frames (a debugger stop, a window drag) count as this long.
    // max_ticks: at most this many ticks per frame; the rest of the backlog is dropped so a slow
    // machine slows the game down instead of spiralling.
    explicit FixedStep(double max_frame_seconds = 0.25, int max_ticks = 5)
        : max_frame_(max_frame_seconds), max_ticks_(max_ticks) {}

    StepPlan advance(double real_dt_seconds);
    void reset() { accumulator_ = 0.0; }
    double accumulator() const { return accumulator_; }

  private:
    double max_frame_;
    int max_ticks_;
    double accumulator_ = 0.0;
};

}  // namespace bz::game
