#pragma once
// A counterexample of `holon verify --every-size` lives on the window grown by one, a region no
// --region option can name, so no other command could read its trace back. This moves it onto the
// smallest region that can be named (square:WxH, cubic:WxHxD, hex:rR) and holds a translate of it,
// the added cells empty without inputs, and has the reference interpreter confirm it there again:
// the trace --trace-out writes is then one `holon check --region R --from TRACE#0` and
// `holon view` read like any other. Cells no step reads or writes are then emptied where the
// interpreter still confirms it, and the region shrunk around what is left.

#include "checker/Trace.h"
#include "checker/Verdict.h"
#include "rules/Model.h"
#include "rules/Region.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

struct NamedCounterexample {
    rules::Region region;
    Trace trace;
    std::vector<std::uint32_t> inputs;
};

/// `r`: a confirmed --every-size counterexample (its witness names the window's radius and the
/// region it was confirmed on). Nothing, with the reason in `why`, when the interpreter does not
/// confirm it on the named region.
std::optional<NamedCounterexample> onNamedRegion(const rules::Model& model, const PropertyResult& r, std::string& why);

}  // namespace holon::checker
