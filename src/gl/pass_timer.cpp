#include "gl/pass_timer.h"

namespace bz::gl {

PassTimer::PassTimer(TimingMethod method) : method_(method) {
    if (method_ == TimingMethod::gpu_queries) {
        for (auto& slot : slots_) glGenQueries(kMaxPasses, slot.queries.data());
    }
}

PassTimer::~PassTimer() {
    if (method_ == TimingMethod::gpu_queries) {
        for (auto& slot : slots_) glDeleteQueries(kMaxPasses, slot.queries.data());
    }
}

void PassTimer::begin_frame() {
    if (method_ == TimingMethod::cpu_finish) {
        current_.clear();
        return;
    }
    if (method_ != TimingMethod::gpu_queries) return;
    ++frame_;
    FrameSlot& slot = slots_[static_cast<std::size_t>(frame_ % kLatency)];
    if (slot.pending) {
        // This slot was filled kLatency frames ago: its results are ready without a stall on
        // any real driver; GL_QUERY_RESULT would wait if not.
        std::vector<PassTime> times;
        for (std::size_t i = 0; i < slot.names.size(); ++i) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(slot.queries[i], GL_QUERY_RESULT, &ns);
            times.push_back({slot.names[i], static_cast<double>(ns) * 1e-6});
        }
        // The very first result can be garbage on some drivers: drop it.
        if (first_discarded_) results_ = std::move(times);
        first_discarded_ = true;
    }
    slot.names.clear();
    slot.pending = false;
}

void PassTimer::end_frame() {
    if (method_ == TimingMethod::cpu_finish) results_ = current_;
}

void PassTimer::begin(const char* name) {
    if (method_ == TimingMethod::cpu_finish) {
        glFinish();
        start_ = std::chrono::steady_clock::now();
        current_.push_back({name, 0.0});
    } else if (method_ == TimingMethod::gpu_queries) {
        FrameSlot& slot = slots_[static_cast<std::size_t>(frame_ % kLatency)];
        if (slot.names.size() >= kMaxPasses) return;
        glBeginQuery(GL_TIME_ELAPSED, slot.queries[slot.names.size()]);
        slot.names.emplace_back(name);
        slot.pending = true;
    }
}

void PassTimer::end() {
    if (method_ == TimingMethod::cpu_finish) {
        glFinish();
        const auto now = std::chrono::steady_clock::now();
        if (!current_.empty()) {
            current_.back().ms = std::chrono::duration<double, std::milli>(now - start_).count();
        }
    } else if (method_ == TimingMethod::gpu_queries) {
        glEndQuery(GL_TIME_ELAPSED);
    }
}

}  // namespace bz::gl
