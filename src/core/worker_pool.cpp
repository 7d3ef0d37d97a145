#include "core/worker_pool.h"

#include <algorithm>

namespace bz {

WorkerPool::WorkerPool(std::size_t max_threads)
    : max_threads_(std::max<std::size_t>(1, max_threads)) {}

WorkerPool::~WorkerPool() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::run(std::size_t tasks, const std::function<void(std::size_t)>& task) {
    tasks = std::min(tasks, max_threads_);
    if (tasks == 0) return;
    if (tasks > 1) {
        // Started on first use: a process that never has enough work starts none.
        while (threads_.size() + 1 < tasks) {
            const std::size_t index = threads_.size();
            threads_.emplace_back([this, index] { work(index); });
        }
        {
            const std::lock_guard lock(mutex_);
            task_ = &task;
            tasks_ = tasks;
            running_ = tasks - 1;
            ++generation_;
        }
        start_.notify_all();
    }
    // The other threads are waited for even if task 0 throws: they hold `task`.
    const auto wait = [&] {
        if (tasks == 1) return;
        std::unique_lock lock(mutex_);
        done_.wait(lock, [this] { return running_ == 0; });
        task_ = nullptr;
    };
    try {
        task(0);
    } catch (...) {
        wait();
        throw;
    }
    wait();
}

void WorkerPool::work(std::size_t index) {
    std::size_t seen = 0;
    // A thread started during a run takes that run (its generation is ahead of `seen`).
    for (;;) {
        const std::function<void(std::size_t)>* task = nullptr;
        {
            std::unique_lock lock(mutex_);
            start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            if (index + 1 < tasks_) task = task_;
        }
        if (!task) continue;  // not needed this run
        (*task)(index + 1);
        {
            const std::lock_guard lock(mutex_);
            if (--running_ == 0) done_.notify_one();
        }
    }
}

}  // namespace bz
