// The checked writer: bad paths refused before any work, write errors reported, never a torn or
// half-written file, nothing left behind when a piecewise write is abandoned.

#include "rules/Error.h"
#include "rules/OutputFile.h"
#include "rules/StopSignals.h"
#include "rules/TextFile.h"

#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using holon::InputError;
using holon::rules::OutputFile;

namespace {
namespace fs = std::filesystem;
std::size_t entries(const fs::path& dir) { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
}  // namespace

TEST_CASE("an output path is checked before the work: a missing folder or a folder as the file") {
    const fs::path dir = fs::temp_directory_path() / "holon_output_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    CHECK_THROWS_WITH_AS(OutputFile("--svg", (dir / "no" / "such.svg").string()), doctest::Contains("does not exist"), InputError);
    CHECK_THROWS_WITH_AS(OutputFile("--svg", dir.string()), doctest::Contains("is a folder"), InputError);
    CHECK_THROWS_AS(OutputFile("--svg", ""), InputError);
    const OutputFile ok("--svg", (dir / "a.svg").string());
    ok.write("first");
    ok.write("second");
    CHECK(holon::rules::readTextFile((dir / "a.svg").string()) == "second");
    CHECK(entries(dir) == 1);  // no temporary left beside it
    fs::remove_all(dir);
}

TEST_CASE("a full device is an error with the reason, not a silent success") {
    if (!fs::exists("/dev/full")) return;
    const OutputFile full("--dot", "/dev/full");
    CHECK_THROWS_WITH_AS(full.write(std::string(1 << 16, 'x')), doctest::Contains("No space left"), InputError);
    auto s = full.open();
    s.stream() << std::string(1 << 16, 'x');
    CHECK_THROWS_AS(s.commit(), InputError);
}

TEST_CASE("a piecewise write appears whole on commit and not at all when abandoned") {
    const fs::path dir = fs::temp_directory_path() / "holon_output_stream_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const OutputFile file("--plan-out", (dir / "plan.jsonl").string());
    {
        auto s = file.open();
        s.stream() << "half";
        CHECK(!fs::exists(dir / "plan.jsonl"));
    }
    CHECK(entries(dir) == 0);
    auto s = file.open();
    s.stream() << "whole\n";
    s.commit();
    CHECK(holon::rules::readTextFile((dir / "plan.jsonl").string()) == "whole\n");
    CHECK(entries(dir) == 1);
    fs::remove_all(dir);
}

TEST_CASE("a signal that ends holon mid-write leaves no temporary behind") {
    // export interrupted while writing a 400 MB world left FILE.tmp-XXXXXX: the process died of the
    // signal with the temporary still open. A child writes and is signalled; it must die of that
    // signal (as before) and leave its folder empty.
    const fs::path dir = fs::temp_directory_path() / "holon_output_signal_test";
    // SIGPIPE is what `holon plan --plan-out FILE | head` gets; 0 stands for std::terminate (an
    // exception no one catches), which ends the child with SIGABRT.
    for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, 0}) {
        CAPTURE(signal);
        fs::remove_all(dir);
        fs::create_directories(dir);
        const pid_t child = ::fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            const rlimit noCore{0, 0};
            ::setrlimit(RLIMIT_CORE, &noCore);      // SIGQUIT and SIGABRT would dump core
            if (signal) ::signal(signal, SIG_DFL);  // as a shell starts holon (ctest may ignore SIGPIPE)
            holon::rules::endOnSignalsCleanly();
            auto s = OutputFile("--visiblesim", (dir / "world.xml").string()).open();
            s.stream() << std::string(1 << 20, 'x');
            s.stream().flush();
            if (signal) ::raise(signal);
            else std::terminate();
            ::_exit(0);  // not reached: the signal ends the child
        }
        int status = 0;
        REQUIRE(::waitpid(child, &status, 0) == child);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == (signal ? signal : SIGABRT));
        CHECK(entries(dir) == 0);
    }
    // The same registry, asked directly: a stream being written is listed until it is committed.
    fs::remove_all(dir);
    fs::create_directories(dir);
    auto s = OutputFile("--plan-out", (dir / "plan.jsonl").string()).open();
    s.stream() << "half";
    CHECK(entries(dir) == 1);
    holon::rules::removeTemporaries();
    CHECK(entries(dir) == 0);
    fs::remove_all(dir);
}

TEST_CASE("an output folder is created, but not its missing parent, and a file is not a folder") {
    using holon::rules::prepareOutputDir;
    const fs::path dir = fs::temp_directory_path() / "holon_output_dir_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    prepareOutputDir("--out", (dir / "new").string());
    CHECK(fs::is_directory(dir / "new"));
    prepareOutputDir("--out", (dir / "new").string());  // an existing folder is fine
    prepareOutputDir("--out", (dir / "slash" / "").string());
    CHECK(fs::is_directory(dir / "slash"));
    CHECK_THROWS_WITH_AS(prepareOutputDir("--out", (dir / "typo" / "new").string()), doctest::Contains("--out"), InputError);
    CHECK(!fs::exists(dir / "typo"));
    std::ofstream(dir / "file") << "x";
    CHECK_THROWS_WITH_AS(prepareOutputDir("--out", (dir / "file").string()), doctest::Contains("is not a folder"), InputError);
    CHECK_THROWS_WITH_AS(prepareOutputDir("--out", (dir / "file" / "sub").string()), doctest::Contains("is not a folder"), InputError);
    CHECK_THROWS_AS(prepareOutputDir("--out", ""), InputError);
    fs::remove_all(dir);
}

TEST_CASE("while a job's outputs are claimed, no two options write the same file or into another's folder") {
    using holon::rules::OutputClaims;
    const fs::path dir = fs::temp_directory_path() / "holon_output_claims_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string plan = (dir / "plan.jsonl").string(), out = (dir / "out").string();
    {
        const OutputClaims claims;
        OutputFile("--plan-out", plan);
        OutputFile("--plan-out", plan);  // one option may check its file twice (before and after the work)
        // A plan's --html once replaced its --plan-out, with exit 0.
        CHECK_THROWS_WITH_AS(OutputFile("--html", (dir / "." / "plan.jsonl").string()), doctest::Contains(": --plan-out writes there too"), InputError);
        holon::rules::prepareOutputDir("--out", out);
        OutputFile("--out", out + "/summary.json");  // the folder's own files
        CHECK_THROWS_WITH_AS(OutputFile("--trace-out", out + "/summary.json"), doctest::Contains("lies in the folder --out writes"), InputError);
        CHECK_THROWS_WITH_AS(holon::rules::prepareOutputDir("--hex-disks", dir.string()), doctest::Contains("holds --plan-out's file"), InputError);
        // A folder whose option declares its files shares the rest: plan --out run --plan-out run/plan.jsonl.
        const std::string run = (dir / "run").string();
        holon::rules::prepareOutputDir("--out", run, {"summary.json", "snapshot-*.svg"});
        OutputFile("--plan-out", run + "/plan.jsonl");
        CHECK_THROWS_WITH_AS(OutputFile("--html", run + "/snapshot-end.svg"), doctest::Contains("--out writes a file of that name in its folder"), InputError);
        CHECK_THROWS_WITH_AS(holon::rules::prepareOutputDir("--smt-out", run, {"x.smt2"}), doctest::Contains("--out writes there too"), InputError);
        OutputClaims::reading("the input", (dir / "trace.json").string());
        CHECK_THROWS_WITH_AS(OutputFile("-o", (dir / "trace.json").string()), doctest::Contains("is also read as the input"), InputError);
        CHECK_THROWS_AS(OutputClaims(), holon::InternalError);  // one job at a time
    }
    // Without a job's claims (the library's default), nothing is compared.
    OutputFile("--plan-out", plan);
    OutputFile("--html", plan);
    fs::remove_all(dir);
}
