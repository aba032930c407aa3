// Allocator selection by name, and what every allocator needs to know about a transfer.

#include "planner/Allocator.h"
#include "planner/Execution.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <iterator>

namespace holon::planner {

std::unique_ptr<Allocator> randomAllocator(std::uint64_t seed);
std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed);
std::unique_ptr<Allocator> optimalAllocator(const Problem& problem, std::uint64_t seed);
std::unique_ptr<Allocator> demandAllocator(const Problem& problem, std::uint64_t seed, bool eager);

std::pair<std::int64_t, std::int64_t> transferEnds(const Execution& ex, std::int64_t anchor, int shape) {
    const BoxEngine& engine = ex.engine();
    const auto& t = engine.tables().shape(shape);
    const auto& steps = engine.cellSteps(shape);
    std::int64_t from = -1, to = -1;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::int64_t i = anchor + steps[k];
        const BoxEngine::Value v = ex.cells()[i], w = static_cast<BoxEngine::Value>(t.rhs[k][v]);
        const auto before = engine.tables().massUnitsOf(v), after = engine.tables().massUnitsOf(w);
        if (after < before) from = i;
        if (after > before) to = i;
    }
    if (from < 0 || to < 0) return {-1, -1};
    return {from, to};
}

namespace {
constexpr std::pair<AllocatorKind, const char*> kNames[] = {{AllocatorKind::Random, "random"},
                                                            {AllocatorKind::Gradient, "gradient"},
                                                            {AllocatorKind::Demand, "demand"},
                                                            {AllocatorKind::Eager, "eager"},
                                                            {AllocatorKind::Optimal, "optimal"}};
}  // namespace

std::string allocatorChoices() {
    std::string choices;
    const std::size_t n = std::size(kNames);
    for (std::size_t k = 0; k < n; ++k) {
        if (k > 0) choices += k + 1 == n ? " or " : ", ";
        choices += kNames[k].second;
    }
    return choices;
}

AllocatorKind allocatorKind(const std::string& name) {
    for (const auto& [kind, known] : kNames)
        if (name == known) return kind;
    throw InputError(rules::parameterName(rules::Parameter::Allocator) + " '" + name + "': choose " + allocatorChoices(), rules::Parameter::Allocator);
}

std::unique_ptr<Allocator> makeAllocator(AllocatorKind kind, const Problem& problem, std::uint64_t seed) {
    switch (kind) {
    case AllocatorKind::Random: return randomAllocator(seed);
    case AllocatorKind::Gradient: return gradientAllocator(problem, seed);
    case AllocatorKind::Demand: return demandAllocator(problem, seed, false);
    case AllocatorKind::Eager: return demandAllocator(problem, seed, true);
    case AllocatorKind::Optimal: return optimalAllocator(problem, seed);
    }
    throw InternalError("makeAllocator: an AllocatorKind out of range");
}

std::unique_ptr<Allocator> makeAllocator(const std::string& name, const Problem& problem, std::uint64_t seed) { return makeAllocator(allocatorKind(name), problem, seed); }

}  // namespace holon::planner
