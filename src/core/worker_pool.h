#pragma once
// Threads kept for the CPU work a frame does before the GPU starts (culling a big instance's
// clusters; parallel_chunks.h). Starting a thread and joining it cost 0.2 ms a time on the
// 2-core test machine, as much as the share of the culling it took over
// (docs/measurements/edge-clusters.md); kept threads sleep on a condition variable between
// frames and are woken for each run. Owned by whoever runs such work (the renderer), started
// on first use.
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace bz {

class WorkerPool {
  public:
    // At most `max_threads` tasks run at once, the caller's own thread included.
    explicit WorkerPool(std::size_t max_threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    std::size_t max_threads() const { return max_threads_; }
    // Runs task(0) .. task(tasks - 1), each on its own thread (task 0 on the caller's), and
    // returns when all are done. tasks <= max_threads().
    void run(std::size_t tasks, const std::function<void(std::size_t)>& task);

  private:
    void work(std::size_t index);  // thread `index` (task index + 1 of its runs)

    std::size_t max_threads_;
    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    const std::function<void(std::size_t)>* task_ = nullptr;
    std::size_t tasks_ = 0;       // of the current run
    std::size_t generation_ = 0;  // runs started: a thread takes each one once
    std::size_t running_ = 0;     // threads of the current run not yet done
    bool stopping_ = false;
};

}  // namespace bz
