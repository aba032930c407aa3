#pragma once
// The one hook through which every back-end reports the rule instances it applies to its ensemble:
// the compiled engine (BoxEngine::apply, which the U/P/F planner, hex sculpting and hex disks write
// through) and the back-ends that run the reference interpreter (Roombots coordination). A test
// installs a Recorder and replays what it hears through rules::Interpreter
// (tests/planner/ConformanceTest.cpp): a write to an ensemble that no reported instance explains
// shows up there as a difference. Without a Recorder the hook costs one thread-local test.

#include "planner/BoxEngine.h"
#include "rules/Interpreter.h"

#include <functional>

namespace holon::planner {

/// One rule instance about to be applied, with the ensemble as it is before. Either a compiled
/// engine's instance on `cells` (board indices), or an interpreter's on `configuration`.
struct Applied {
    const BoxEngine* engine = nullptr;
    const BoxEngine::Value* cells = nullptr;
    std::int64_t anchor = 0;
    int shape = 0;
    const rules::Interpreter* interpreter = nullptr;
    const rules::Configuration* configuration = nullptr;
    rules::Instance instance;
};

class Recorder {
public:
    /// While it lives, `hook` hears every instance applied on this thread.
    explicit Recorder(std::function<void(const Applied&)> hook);
    ~Recorder();
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    static bool active() { return current_ != nullptr; }
    static void report(const Applied& a) {
        if (current_) current_->hook_(a);
    }

private:
    std::function<void(const Applied&)> hook_;
    Recorder* outer_;
    static thread_local Recorder* current_;
};

}  // namespace holon::planner
