#pragma once
// Limits on what user input may ask for, in one place. Each keeps a hostile or mistaken input (a
// script gone wrong, a fuzzer, /dev/zero) from crashing holon or exhausting the machine, and each is
// reported with the place and the limit, never silently applied.
//
// The front end's limits are far above what a design needs: the bundled library's longest
// expression has 5 operators, its rules at most 19 cells, its systems at most 4 fields. Sizes
// computed from input (a shape's sides times --scale, a region's sides) are multiplied with an
// overflow check: a product that wraps modulo 2^64 would pass any size guard as a small one. A
// job's memory is estimated from them and checked against --memory before it allocates (exit 3,
// the limit named), not found out by the kernel.

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>

namespace holon::rules {

/// The memory bound of every job (--memory) unless the user sets one.
constexpr std::uint64_t kDefaultMemoryBytes = std::uint64_t{16} << 30;

/// Bytes read from any one input file (rule file, configuration, mask, picture, shape).
constexpr std::size_t kMaxFileBytes = std::size_t(64) << 20;
/// Bytes of a rule file: its tokens take about 50 bytes per byte of text in the worst case.
constexpr std::size_t kMaxRuleFileBytes = std::size_t(4) << 20;
/// Depth of an expression tree, counting each operator of a chain (`a + b + c` is 2 deep) as every
/// pass over expressions (printer, interpreter, compiled guards, SMT encoding) recurses that deep.
constexpr int kMaxExprDepth = 256;
/// Nesting of JSON values in a configuration or trace (holon's own are at most 6 deep).
constexpr int kMaxJsonDepth = 64;
/// Errors reported per file before the front end stops, like a compiler's -ferror-limit.
constexpr int kMaxErrors = 20;
/// Characters of one identifier.
constexpr int kMaxIdentifier = 256;
/// Pattern cells of one rule (a hex hole move reads 19); the compiled tables are sized by it.
constexpr int kMaxRuleCells = 20;
/// Fields of a system and inputs of a system (an input is one bit of a cell's input mask).
constexpr int kMaxFields = 64;
/// The largest coordinate, in absolute value, of a cell that a shape, a configuration or model
/// file (VisibleSim, binvox) may give and a scaled shape may reach: far beyond any shape that fits
/// in memory, and small enough that a board's extents, a difference of two coordinates and that
/// plus one never overflow an int.
constexpr int kMaxCoordinate = 1 << 29;
/// Values of one enum or integer field.
constexpr int kMaxFieldValues = 256;
constexpr int kMaxInputs = 32;

/// The product of the factors, or UINT64_MAX when it does not fit in 64 bits (so that it fails
/// every size limit).
inline std::uint64_t checkedProduct(std::initializer_list<std::uint64_t> factors) {
    std::uint64_t product = 1;
    for (std::uint64_t f : factors)
        if (__builtin_mul_overflow(product, f, &product)) return std::numeric_limits<std::uint64_t>::max();
    return product;
}

/// A count for messages: a saturated checkedProduct reads "more than 2^64".
inline std::string countText(std::uint64_t n) {
    return n == std::numeric_limits<std::uint64_t>::max() ? std::string("more than 2^64") : std::to_string(n);
}

/// Refuses a job whose estimated memory `bytes` is over `budgetBytes` (the memory bound), before
/// it allocates: LimitError (exit 3) saying what needs it, how much, and the parameter to raise.
inline void requireMemory(std::uint64_t bytes, std::uint64_t budgetBytes, const std::string& what) {
    if (bytes <= budgetBytes) return;
    // Under a tenth of a GiB in MiB: "0.0 GiB, more than --memory 16 MiB" said nothing.
    char need[32];
    if (bytes < (std::uint64_t{1} << 30) / 10) std::snprintf(need, sizeof need, "%llu MiB", static_cast<unsigned long long>((bytes >> 20) + 1));
    else std::snprintf(need, sizeof need, "%.1f GiB", static_cast<double>(bytes) / double(1 << 30));
    const std::string memory = parameterName(Parameter::Memory);
    throw LimitError(what + " needs about " + need + ", more than " + memory + " " + std::to_string(budgetBytes >> 20) + " MiB; raise " + memory + " or give a smaller job",
                     Parameter::Memory);
}

}  // namespace holon::rules
