#pragma once
// The front end's limits, in one place. Each keeps a hostile or mistaken input (a script gone
// wrong, a fuzzer, /dev/zero) from crashing holon or exhausting the machine, and each is reported
// with the place and the limit, never silently applied. They are far above what a design needs:
// the bundled library's longest expression has 5 operators, its rules at most 19 cells, its
// systems at most 4 fields.

#include <cstddef>

namespace holon::rules {

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
/// Values of one enum or integer field.
constexpr int kMaxFieldValues = 256;
constexpr int kMaxInputs = 32;

}  // namespace holon::rules
