#pragma once
// The outcome of checking one property, with its evidence.

#include "checker/Trace.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace holon::checker {

enum class Verdict { Holds, Violated, Unknown };
std::string verdictName(Verdict v);

struct PropertyResult {
    std::string name, kind;
    Verdict verdict = Verdict::Unknown;
    std::string summary;            // one line for the table
    nlohmann::json witness = nullptr;  // machine-readable evidence
    double seconds = 0;
    std::optional<Trace> trace;
};

}  // namespace holon::checker
