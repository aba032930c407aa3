#pragma once
// Threads that live for the whole of a search and run one job per round: run(job) calls job(t)
// on every thread t (t = 0 on the caller) and returns when all have finished. The explorer runs
// a round per chunk of a breadth-first level, the planner a job per phase of a synchronous round;
// starting threads for each chunk cost a clone and a wake-up per thread, which on this
// paravirtualised host was 5% of a two-thread search.
//
// A job that throws (std::bad_alloc when a worker's buffer cannot grow) must neither abort the
// process (an exception leaving a thread's function calls std::terminate) nor let the caller
// unwind while other threads still run on its data: each thread catches, the round still ends at
// the barrier with every thread back, and run() then rethrows the first exception on the caller.
// A thread that cannot be created leaves the pool smaller, not broken.

#include <barrier>
#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace holon::rules {

class WorkerPool {
public:
    explicit WorkerPool(int threads) : start_(threads), end_(threads) {
        for (int t = 1; t < threads; ++t) {
            try {
                helpers_.emplace_back([this, t] {
                    while (true) {
                        start_.arrive_and_wait();
                        if (stop_) return;
                        guarded(t);
                        end_.arrive_and_wait();
                    }
                });
            } catch (const std::system_error&) {
                // No more threads: the barriers stop waiting for the ones never started.
                for (int missing = t; missing < threads; ++missing) start_.arrive_and_drop(), end_.arrive_and_drop();
                break;
            }
        }
    }
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;
    ~WorkerPool() {
        stop_ = true;
        start_.arrive_and_wait();
        for (std::thread& h : helpers_) h.join();
    }
    int threads() const { return static_cast<int>(helpers_.size()) + 1; }
    /// Runs job(t) on every thread; rethrows the first exception a thread's job threw, once all
    /// threads have finished the round.
    void run(const std::function<void(int)>& job) {
        job_ = &job;
        failure_ = nullptr;
        start_.arrive_and_wait();
        guarded(0);
        end_.arrive_and_wait();
        if (failure_) std::rethrow_exception(failure_);
    }

private:
    void guarded(int t) {
        try {
            (*job_)(t);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(failureMutex_);
            if (!failure_) failure_ = std::current_exception();
        }
    }

    std::barrier<> start_, end_;  // a round's start and end; each synchronises the threads' memory
    const std::function<void(int)>* job_ = nullptr;
    bool stop_ = false;
    std::mutex failureMutex_;
    std::exception_ptr failure_;
    std::vector<std::thread> helpers_;
};

}  // namespace holon::rules
