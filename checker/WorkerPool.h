#pragma once
// Threads that live for the whole of a search and run one job per round: run(job) calls job(t)
// on every thread t (t = 0 on the caller) and returns when all have finished. The explorer runs
// a round per chunk of a breadth-first level; starting threads for each chunk cost a clone and
// a wake-up per thread, which on this paravirtualised host was 5% of a two-thread search.

#include <barrier>
#include <functional>
#include <thread>
#include <vector>

namespace holon::checker {

class WorkerPool {
public:
    explicit WorkerPool(int threads) : start_(threads), end_(threads) {
        for (int t = 1; t < threads; ++t)
            helpers_.emplace_back([this, t] {
                while (true) {
                    start_.arrive_and_wait();
                    if (stop_) return;
                    (*job_)(t);
                    end_.arrive_and_wait();
                }
            });
    }
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;
    ~WorkerPool() {
        stop_ = true;
        start_.arrive_and_wait();
        for (std::thread& h : helpers_) h.join();
    }
    int threads() const { return static_cast<int>(helpers_.size()) + 1; }
    void run(const std::function<void(int)>& job) {
        job_ = &job;
        start_.arrive_and_wait();
        job(0);
        end_.arrive_and_wait();
    }

private:
    std::barrier<> start_, end_;  // a round's start and end; each synchronises the threads' memory
    const std::function<void(int)>* job_ = nullptr;
    bool stop_ = false;
    std::vector<std::thread> helpers_;
};

}  // namespace holon::checker
