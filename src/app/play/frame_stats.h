#pragma once
// Frame times of a play run: the on-screen frame-rate readout (averaged over the last half
// second, so it can be read) and the percentiles `beamzone.log` gets at exit.
#include <string>
#include <vector>

namespace bz::app {

class FrameStats {
  public:
    void add(double seconds);  // one frame's wall time
    std::size_t count() const { return frames_.size(); }
    // The p-th percentile (0..100) of all frame times, in milliseconds (nearest rank).
    double percentile_ms(double p) const;
    // "60 FPS  16.7 MS" over the last readout window; empty before the first window closes.
    const std::string& readout() const { return readout_; }
    // "frame times over N frames: mean 16.7 ms (59.9 fps), p50 16.6 ms, p90 ..., p99 ...,
    // max ... ms", or a note that there were none.
    std::string summary() const;

  private:
    std::vector<float> frames_;
    double window_seconds_ = 0.0;
    int window_frames_ = 0;
    double window_max_ = 0.0;
    std::string readout_;
};

}  // namespace bz::app
