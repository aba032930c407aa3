#pragma once
// One budget for every long phase of a check: a wall-clock deadline fixed when the job starts
// (OMPL's termination condition, reduced to what holon needs), so exploration and every phase after
// it (holonomy, deadlock classification) share one --timeout instead of each starting its own.

#include <chrono>

namespace holon::checker {

class Budget {
public:
    /// `seconds` <= 0: no deadline.
    explicit Budget(double seconds = 0) : seconds_(seconds), start_(Clock::now()) {}
    bool limited() const { return seconds_ > 0; }
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    /// Seconds left (0 once expired); meaningful only when limited().
    double remaining() const { return seconds_ - elapsed() > 0 ? seconds_ - elapsed() : 0; }
    bool expired() const { return limited() && elapsed() >= seconds_; }

private:
    using Clock = std::chrono::steady_clock;
    double seconds_;
    Clock::time_point start_;
};

}  // namespace holon::checker
