#pragma once
// Axes for a Canvas: data ranges mapped into a plot rectangle, "nice" tick steps, grid, tick
// labels, axis labels and a title.
#include <string>

#include "app/plot/plot_canvas.h"

namespace bz::app {

struct Axis {
    double lo = 0.0;
    double hi = 1.0;
    std::string label;
};

// A round step (1, 2 or 5 times a power of ten) giving about `target` ticks over `range`.
double nice_step(double range, int target);
// Enough decimals to tell ticks `step` apart.
std::string tick_label(double v, double step);
// Widens [lo, hi] outwards to multiples of a nice step (and away from zero width).
Axis nice_axis(double lo, double hi, std::string label, int target_ticks = 6);

class Chart {
  public:
    // The plot area leaves margins for labels inside the canvas.
    Chart(Canvas& canvas, Axis x, Axis y, std::string title);
    glm::vec2 map(double x, double y) const;
    // Grid, axes, ticks, labels and the title.
    void draw_frame();
    // Legend rows from the top-right corner of the plot area inward.
    void legend_entry(int row, const std::string& name, glm::vec3 color);
    glm::vec2 plot_lo() const { return lo_; }
    glm::vec2 plot_hi() const { return hi_; }
    // The lowest y the title's letters reach (y grows upward): labels must stay below it.
    float title_bottom() const;

    static constexpr float kTitleHeight = 15.0f;

  private:
    float title_baseline() const;

    Canvas& canvas_;
    Axis x_, y_;
    std::string title_;
    glm::vec2 lo_, hi_;
};

inline constexpr glm::vec3 kInk{0.1f, 0.1f, 0.1f};
inline constexpr glm::vec3 kGrid{0.86f, 0.86f, 0.86f};
inline constexpr glm::vec3 kPaper{1.0f, 1.0f, 1.0f};
// Distinct colours for series, in order.
glm::vec3 series_color(std::size_t i);

}  // namespace bz::app
