#pragma once
// Compiler-style diagnostics: collected per phase, sorted, printed as file:line:col with the source
// line and a caret. Warnings have names and can be switched off.

#include "rules/Ir.h"

#include <set>
#include <string>
#include <vector>

namespace holon::rules {

struct Diagnostic {
    enum class Severity { Error, Warning } severity = Severity::Error;
    SourceLoc loc;
    int line = 0, col = 0;  // copied from loc (SourceLoc does not compare)
    std::string message;
    std::string name;  // warnings only: the name that silences it, e.g. "unused-value"
};

class Diagnostics {
public:
    Diagnostics(std::string fileName, std::string source);

    void error(SourceLoc loc, std::string message);
    void warning(SourceLoc loc, std::string name, std::string message);
    void silence(const std::string& warningName) { silenced_.insert(warningName); }
    /// Every warning name holon emits, for `--help` and for checking -Wno-NAME arguments.
    static const std::vector<std::string>& warningNames();

    bool hasErrors() const { return errors_ > 0; }
    int errorCount() const { return errors_; }
    const std::vector<Diagnostic>& all() const { return diagnostics_; }
    /// Sorted by position, each with its source line and a caret.
    std::string render() const;

private:
    std::string fileName_;
    std::vector<std::string> lines_;
    std::vector<Diagnostic> diagnostics_;
    std::set<std::string> silenced_;
    int errors_ = 0;
};

}  // namespace holon::rules
