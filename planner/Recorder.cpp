// The thread-local slot of the back-end recording hook (Recorder.h); recorders nest.

#include "planner/Recorder.h"

namespace holon::planner {

thread_local Recorder* Recorder::current_ = nullptr;

Recorder::Recorder(std::function<void(const Applied&)> hook) : hook_(std::move(hook)), outer_(current_) { current_ = this; }

Recorder::~Recorder() { current_ = outer_; }

}  // namespace holon::planner
