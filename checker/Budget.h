#pragma once
// One budget for every long phase of a check: a wall-clock deadline fixed when the job starts
// (OMPL's termination condition, reduced to what holon needs), so exploration and every phase after
// it (holonomy, deadlock classification) share one --timeout instead of each starting its own.

#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>

namespace holon::checker {

/// Thrown where a phase that cannot be stopped in the middle otherwise (verify building its
/// formulas) finds its budget spent; the caller makes the verdict unknown.
class OutOfTime : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Budget {
public:
    /// `seconds` <= 0: no deadline.
    explicit Budget(double seconds = 0) : seconds_(seconds), start_(Clock::now()) {}
    bool limited() const { return seconds_ > 0; }
    double seconds() const { return seconds_; }
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    /// Seconds left (0 once expired); meaningful only when limited().
    double remaining() const { return seconds_ - elapsed() > 0 ? seconds_ - elapsed() : 0; }
    bool expired() const { return limited() && elapsed() >= seconds_; }
    /// Throws OutOfTime once expired; `during` says what was cut short ("building the formulas").
    void check(const char* during) const {
        if (!expired()) return;
        std::ostringstream text;
        text << "timeout (" << seconds_ << " s) while " << during;
        throw OutOfTime(text.str());
    }

private:
    using Clock = std::chrono::steady_clock;
    double seconds_;
    Clock::time_point start_;
};

}  // namespace holon::checker
