// Allocator selection by name, and what every allocator needs to know about a transfer.

#include "planner/Allocator.h"
#include "planner/Execution.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

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

std::unique_ptr<Allocator> makeAllocator(const std::string& name, const Problem& problem, std::uint64_t seed) {
    if (name == "random") return randomAllocator(seed);
    if (name == "gradient") return gradientAllocator(problem, seed);
    if (name == "optimal") return optimalAllocator(problem, seed);
    if (name == "demand") return demandAllocator(problem, seed, false);
    if (name == "eager") return demandAllocator(problem, seed, true);
    throw InputError(rules::parameterName(rules::Parameter::Allocator) + " '" + name + "': choose random, gradient, demand, eager or optimal", rules::Parameter::Allocator);
}

}  // namespace holon::planner
