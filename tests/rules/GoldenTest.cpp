// Golden diagnostics: every tests/rules/golden/NAME.holon is parsed and its rendered diagnostics
// are compared with NAME.err (empty or missing: no diagnostics). HOLON_UPDATE_GOLDEN=1 rewrites
// the .err files from the current output, for review with git diff.

#include "rules/Diagnostics.h"
#include "rules/Parser.h"
#include "rules/TextFile.h"

#include <cstdlib>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace holon::rules;
namespace fs = std::filesystem;

TEST_CASE("golden diagnostics for good and bad rule files") {
    const fs::path dir = fs::path(HOLON_TEST_DIR) / "rules" / "golden";
    const bool update = std::getenv("HOLON_UPDATE_GOLDEN") != nullptr;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".holon") continue;
        ++files;
        const std::string text = readTextFile(entry.path().string());
        Diagnostics diagnostics(entry.path().filename().string(), text);
        parseSystem(text, diagnostics);
        const std::string actual = diagnostics.render();
        fs::path expectedPath = entry.path();
        expectedPath.replace_extension(".err");
        if (update) {
            if (actual.empty()) fs::remove(expectedPath);
            else std::ofstream(expectedPath) << actual;
            continue;
        }
        std::string expected;
        if (fs::exists(expectedPath)) expected = readTextFile(expectedPath.string());
        CAPTURE(entry.path().filename().string());
        CHECK(actual == expected);
    }
    CHECK(files >= 10);
}

TEST_CASE("three separate mistakes give three located errors") {
    const std::string text = readTextFile((fs::path(HOLON_TEST_DIR) / "rules/golden/three_mistakes.holon").string());
    Diagnostics diagnostics("three_mistakes.holon", text);
    CHECK_FALSE(parseSystem(text, diagnostics).has_value());
    REQUIRE(diagnostics.errorCount() == 3);
    CHECK(diagnostics.all()[0].line == 5);
    CHECK(diagnostics.all()[1].line == 6);
    CHECK(diagnostics.all()[2].line == 7);
}

TEST_CASE("warnings can be silenced by name") {
    const std::string text = readTextFile((fs::path(HOLON_TEST_DIR) / "rules/golden/warnings.holon").string());
    Diagnostics loud("w.holon", text), quiet("w.holon", text);
    for (const std::string& name : Diagnostics::warningNames()) quiet.silence(name);
    CHECK(parseSystem(text, loud).has_value());
    CHECK(parseSystem(text, quiet).has_value());
    CHECK(loud.all().size() >= 4);
    CHECK(quiet.all().empty());
}
