// libFuzzer target for the .holon front end: any byte string must be either rejected with
// diagnostics or accepted; an accepted system must print to text that re-parses to an equal IR.
// The diagnostics stay within the error limit and print no raw control byte (a terminal would act
// on it). Crashes, hangs, leaks and sanitizer reports are failures.

#include "rules/Diagnostics.h"
#include "rules/Limits.h"
#include "rules/Parser.h"
#include "rules/Printer.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    holon::rules::Diagnostics diagnostics("fuzz.holon", text);
    auto system = holon::rules::parseSystem(text, diagnostics);
    const std::string rendered = diagnostics.render();
    if (diagnostics.errorCount() > holon::rules::kMaxErrors) std::abort();
    for (const char c : rendered)
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7f) std::abort();
    if (!system) return 0;
    const std::string printed = holon::rules::printSystem(*system);
    holon::rules::Diagnostics again("printed.holon", printed);
    auto reparsed = holon::rules::parseSystem(printed, again);
    if (!reparsed || !(*reparsed == *system)) std::abort();
    return 0;
}
