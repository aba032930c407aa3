// libFuzzer target for command lines: any byte string, one argument per line, run through the same
// runHolon() the binary runs (cli/App.cpp). Exit codes 0-3 are the contract; 4 (an internal error)
// and crashes, hangs, leaks and sanitizer reports are failures. So that a fuzzed command line cannot
// touch the machine, an argument may not contain '/' or start with '..': files are named by
// aliases, whole or after '=' (@pixel for rules/library/pixel.holon; @start, @target: the planner
// example's configurations), outputs land in a scratch folder, and every check and plan gets a time and
// state limit (a second --timeout or --max-states is a usage error, exit 2). verify, hex and
// roombots are left out: verify forks solver processes and the back-ends run for minutes by design.

#include "cli/Commands.h"

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

std::ostringstream sink;

const std::map<std::string, std::string>& aliases() {
    static const std::map<std::string, std::string> all = {
        {"@pixel", HOLON_SOURCE_DIR "/rules/library/pixel.holon"},
        {"@intermediate", HOLON_SOURCE_DIR "/rules/library/planner_intermediate.holon"},
        {"@general1", HOLON_SOURCE_DIR "/rules/library/planner_general1.holon"},
        {"@holes", HOLON_SOURCE_DIR "/rules/library/hex_holes.holon"},
        {"@lock2", HOLON_SOURCE_DIR "/rules/library/general_lock2.holon"},
        {"@start", HOLON_SOURCE_DIR "/examples/check/planner_start.txt"},
        {"@target", HOLON_SOURCE_DIR "/examples/check/planner_target.txt"},
        {"@split", HOLON_SOURCE_DIR "/tests/cli/split.txt"},
    };
    return all;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    char scratch[] = "/tmp/holon_cli_fuzz_XXXXXX";
    if (!mkdtemp(scratch) || chdir(scratch) != 0) std::abort();
    std::cout.rdbuf(sink.rdbuf());
    std::cerr.rdbuf(sink.rdbuf());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args = {"holon"};
    std::string line;
    for (std::size_t i = 0; i <= size && args.size() < 40; ++i) {
        if (i == size || data[i] == '\n') {
            if (line.find('/') != std::string::npos || line.rfind("..", 0) == 0) return 0;
            const std::size_t at = line.find('@');  // a whole argument, or NAME=@alias
            if (at != std::string::npos && (at == 0 || line[at - 1] == '='))
                if (auto a = aliases().find(line.substr(at)); a != aliases().end()) line = line.substr(0, at) + a->second;
            args.push_back(line), line.clear();
        } else if (line.size() < 200) {
            line += static_cast<char>(data[i]);
        }
    }
    if (args.size() < 2 || (args[1] != "rules" && args[1] != "check" && args[1] != "plan")) return 0;
    if (args[1] != "rules") args.insert(args.end(), {"--timeout", "2"});
    if (args[1] == "check") args.insert(args.end(), {"--max-states", "100000"});
    if (args[1] == "plan") args.insert(args.end(), {"--max-steps", "100000"});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int code = holon::cli::runHolon(static_cast<int>(args.size()), argv.data());
    sink.str({});
    if (code < 0 || code > 3) std::abort();  // an internal error, or a code outside the contract
    return 0;
}
