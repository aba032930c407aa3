#pragma once
// Independent jobs spread over the machine's cores (or `threads`), with an optional progress line on
// a terminal. The first exception a job throws stops the others and is rethrown as it was (an
// InputError stays exit 2, a std::bad_alloc or LimitError a limit), once every worker has joined.
// `budget` is asked before each job: once it is spent, no job starts (a deadline, a signal).

#include "rules/Budget.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace holon::cli {

inline void runParallel(int jobs, int threads, bool progress, const std::string& unit, const std::function<void(int)>& job,
                        const Budget& budget = Budget()) {
    std::atomic<int> next{0}, done{0};
    std::mutex io;
    std::exception_ptr firstError;
    auto worker = [&] {
        for (int j; (j = next++) < jobs;) {
            if (budget.reached()) return;
            try {
                job(j);
            } catch (...) {
                std::lock_guard lock(io);
                if (!firstError) firstError = std::current_exception();
                next = jobs;
                return;
            }
            if (progress) {
                std::lock_guard lock(io);
                std::cerr << "\r[" << ++done << "/" << jobs << " " << unit << "]" << std::flush;
            }
        }
    };
    const int n = std::max(1, std::min(jobs, threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency())));
    std::vector<std::thread> pool;
    try {
        for (int t = 0; t < n; ++t) pool.emplace_back(worker);
    } catch (...) {  // a thread the system would not start: the ones running finish, then the error
        next = jobs;
        for (auto& t : pool) t.join();
        throw;
    }
    for (auto& t : pool) t.join();
    if (progress) std::cerr << '\n';
    if (firstError) std::rethrow_exception(firstError);
}

}  // namespace holon::cli
