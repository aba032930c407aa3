#pragma once
// Compiler-style diagnostics: collected per phase, sorted, printed as file:line:col with an excerpt
// of the source line and a caret. Warnings have names and can be switched off. Like a compiler's
// -ferror-limit, a file stops after kMaxErrors errors: a file of garbage gives a page, not a flood.

#include "rules/Ir.h"
#include "rules/Limits.h"

#include <set>
#include <string>
#include <vector>

namespace holon::rules {

struct Diagnostic {
    enum class Severity { Error,
                          Warning } severity = Severity::Error;
    SourceLoc loc;
    int line = 0, col = 0;  // copied from loc (SourceLoc does not compare)
    std::string message;
    std::string name;  // warnings only: the name that silences it, e.g. "unused-value"
};

class Diagnostics {
public:
    Diagnostics(std::string fileName, std::string source);

    /// Past the error limit the error is dropped and stopped() becomes true.
    void error(SourceLoc loc, std::string message);
    void warning(SourceLoc loc, std::string name, std::string message);
    void silence(const std::string& warningName) { silenced_.insert(warningName); }
    /// Every warning name holon emits, for `--help` and for checking -Wno-NAME arguments.
    static const std::vector<std::string>& warningNames();

    bool hasErrors() const { return errors_ > 0; }
    int errorCount() const { return errors_; }
    /// More errors than the limit came: the phases stop reading the file.
    bool stopped() const { return stopped_; }
    const std::vector<Diagnostic>& all() const { return diagnostics_; }
    /// Sorted by position, each with its source line (an excerpt around the column, escaped) and a caret.
    std::string render() const;

private:
    std::string fileName_, source_;
    std::vector<Diagnostic> diagnostics_;
    std::set<std::string> silenced_;
    int errors_ = 0;
    bool stopped_ = false;
};

}  // namespace holon::rules
