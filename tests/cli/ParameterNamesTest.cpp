// The library's messages name parameters through rules/Parameter.h: a library user sees the API's
// names and never a command-line flag; the CLI, once its table (cli/ParameterNames.cpp) is
// installed, sees the options its help lists.

#include "cli/ParameterNames.h"
#include "planner/Shape.h"
#include "planner/roombots/Assembly.h"
#include "rules/Error.h"
#include "rules/Limits.h"

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

using holon::rules::Parameter;

namespace {

/// Every Parameter, first to last.
std::vector<Parameter> allParameters() {
    std::vector<Parameter> all;
    for (int p = 0; p <= static_cast<int>(Parameter::Robot); ++p) all.push_back(static_cast<Parameter>(p));
    return all;
}

/// The message and the parameter of what `job` throws.
template <typename Error, typename Job>
std::pair<std::string, std::optional<Parameter>> caught(Job job) {
    try {
        job();
    } catch (const Error& e) {
        return {e.what(), e.parameter()};
    }
    FAIL("nothing thrown");
    return {};
}

/// Undoes installOptionNames when a test ends, so the other tests see the API's names.
struct OptionNames {
    OptionNames() { holon::cli::installOptionNames(); }
    ~OptionNames() { holon::rules::setParameterNames(nullptr); }
};

const auto memory = [] { holon::rules::requireMemory(std::uint64_t{3} << 30, std::uint64_t{1} << 30, "the job"); };
const auto scale = [] { holon::planner::parseShape("box:2x2", 0); };
const auto strategy = [] { holon::planner::roombots::parseStrategy("fast"); };

}  // namespace

TEST_CASE("every parameter has an API name without a flag and an option") {
    for (Parameter p : allParameters()) {
        CAPTURE(static_cast<int>(p));
        CHECK(holon::rules::apiParameterName(p).find("--") == std::string::npos);
        CHECK(holon::cli::optionName(p).find("--") != std::string::npos);
    }
}

TEST_CASE("a library error names the API's parameter, not a command-line flag") {
    const auto [m, mp] = caught<holon::LimitError>(memory);
    CHECK(m == "the job needs about 3.0 GiB, more than Limits::memoryBytes 1024 MiB; raise Limits::memoryBytes or give a smaller job");
    CHECK(mp == Parameter::Memory);
    const auto [s, sp] = caught<holon::InputError>(scale);
    CHECK(s == "shape 'box:2x2': scale (parseShape) must be at least 1");
    CHECK(sp == Parameter::Scale);
    const auto [t, tp] = caught<holon::InputError>(strategy);
    CHECK(t.find("roombots::Strategy: unknown strategy 'fast'") == 0);
    CHECK(tp == Parameter::Strategy);
    for (const std::string& message : {m, s, t}) CHECK(message.find("--") == std::string::npos);
}

TEST_CASE("with the CLI's names installed, the same errors name the options") {
    const OptionNames installed;
    CHECK(caught<holon::LimitError>(memory).first == "the job needs about 3.0 GiB, more than --memory 1024 MiB; raise --memory or give a smaller job");
    CHECK(caught<holon::InputError>(scale).first == "shape 'box:2x2': --scale must be at least 1");
    CHECK(caught<holon::InputError>(strategy).first == "--strategy: unknown strategy 'fast'; use greedy, slope, step or reserve");
    CHECK(holon::rules::parameterName(Parameter::MakeClouds) == "holon roombots --make-clouds");
}
