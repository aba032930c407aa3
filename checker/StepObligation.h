#pragma once
// One obligation of `holon verify --every-size` that one step of one rule instance decides
// (checker/EverySize.cpp runs it): its query on the window, its query on a bounded region (to
// complete a window counterexample), and the property whose type confirms that counterexample.

#include "checker/SmtEncoding.h"
#include "checker/Window.h"

#include <functional>
#include <string>

namespace holon::checker {

/// One property (or conjunct) decided by a step, three ways: on the window (instance q at the
/// origin), on a bounded region (every hypothesis), and on a concrete step through the compiled engine.
struct StepObligation {
    using State = SmtEncoding::State;
    std::string name, kind, proved, broken;  // verdict texts
    int margin = 0;
    /// About one configuration, not a step (checker/EverySizeProgress.h): asked once, with the
    /// window's origin as its cell; a model is a window where the certificate fails, which says
    /// nothing about a region (no completion, no confirmation).
    bool atCell = false;
    std::function<smt::Term(SmtEncoding&, const Window&, int q, const State& c, const State& d)> onWindow;
    std::function<smt::Term(SmtEncoding&, int q, const State& c, const State& d)> onRegion;
    const rules::Property* property = nullptr;  // whose type confirms a counterexample (checker/Property.h)
};

}  // namespace holon::checker
