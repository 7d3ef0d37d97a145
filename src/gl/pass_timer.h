#pragma once
// Times named passes. Two methods, because llvmpipe's GL_TIME_ELAPSED leaves out vertex and
// geometry work:
//  - gpu_queries: GL timer queries, read back `latency` frames later so they never stall;
//  - cpu_finish: glFinish before and after each pass with a steady CPU clock.
#include <array>
#include <chrono>
#include <string>
#include <vector>

#include "gl/gl.h"

namespace bz::gl {

enum class TimingMethod { cpu_finish, gpu_queries, off };

struct PassTime {
    std::string name;
    double ms = 0.0;
};

class PassTimer {
  public:
    explicit PassTimer(TimingMethod method = TimingMethod::off);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    TimingMethod method() const { return method_; }
    // Frames between a frame's end_frame() and its times showing in last_results(): 0 for
    // cpu_finish; for gpu_queries the read-back delay (and the very first frame is dropped).
    int latency() const { return method_ == TimingMethod::gpu_queries ? kLatency : 0; }
    void begin_frame();
    void end_frame();
    void begin(const char* name);
    void end();
    // Times of the most recent frame whose results are available (same frame for cpu_finish;
    // a few frames old for gpu_queries). Empty until the first results arrive.
    const std::vector<PassTime>& last_results() const { return results_; }

  private:
    static constexpr int kLatency = 4;
    static constexpr int kMaxPasses = 16;
    struct FrameSlot {
        std::vector<std::string> names;
        std::array<GLuint, kMaxPasses> queries{};
        bool pending = false;
    };
    TimingMethod method_;
    std::array<FrameSlot, kLatency> slots_{};
    int frame_ = 0;
    bool first_discarded_ = false;
    std::chrono::steady_clock::time_point start_;
    std::vector<PassTime> current_;
    std::vector<PassTime> results_;
};

}  // namespace bz::gl
