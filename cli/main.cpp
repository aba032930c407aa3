// The `holon` command: one binary, a subcommand per job. Exit codes are the same for every
// subcommand (cli/Commands.h): 0 success, 1 a checked property does not hold, 2 bad input or
// usage, 3 undecided, 4 an internal error. Standard output is checked at the end: a report that
// did not reach its reader (a full disk, /dev/full) is an error, not a success.

#include "cli/Commands.h"
#include "rules/Error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <streambuf>
#include <unistd.h>

namespace {

/// std::cout's buffer when standard output is not a terminal: it keeps the first write error's
/// reason, which stdio loses once later calls reset errno (a report larger than stdio's buffer
/// sent to /dev/full fails long before the end). On a terminal stdio's line buffering stays.
class CheckedStdout : public std::streambuf {
public:
    void install() {
        setp(buffer_, buffer_ + sizeof buffer_);
        original_ = std::cout.rdbuf(this);
    }
    ~CheckedStdout() override {
        if (!original_) return;
        drain();
        std::cout.rdbuf(original_);  // the library flushes std::cout after this object is gone
    }
    int error() const { return error_; }

protected:
    int overflow(int c) override {
        if (!drain()) return traits_type::eof();
        if (c != traits_type::eof()) *pptr() = static_cast<char>(c), pbump(1);
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const char* p = pbase();
        std::size_t n = static_cast<std::size_t>(pptr() - pbase());
        setp(buffer_, buffer_ + sizeof buffer_);
        if (error_) return false;  // what follows a lost piece is not written either
        while (n > 0) {
            const ssize_t w = ::write(STDOUT_FILENO, p, n);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) {
                error_ = w < 0 ? errno : EIO;
                return false;
            }
            p += w, n -= static_cast<std::size_t>(w);
        }
        return true;
    }
    char buffer_[1 << 16];
    std::streambuf* original_ = nullptr;
    int error_ = 0;
};

CheckedStdout checkedStdout;

/// Flushes standard output; empty when everything written to it arrived, else the reason.
std::string stdoutFailure() {
    errno = 0;
    std::cout.flush();
    int err = checkedStdout.error() ? checkedStdout.error() : errno;
    // On a terminal std::cout writes through stdio; its first failing flush holds the reason.
    const bool flushed = std::fflush(stdout) == 0;
    if (!flushed && err == 0) err = errno;
    if (flushed && std::cout.good() && !std::ferror(stdout) && !checkedStdout.error()) return {};
    return err != 0 ? std::strerror(err) : "an earlier write failed";
}

/// What to change when a subcommand runs out of the machine's memory: the options that size its
/// work. check's own --memory bound stops it cleanly first unless it is set above what is free.
std::string memoryAdvice(const std::string& command) {
    if (command == "check") return "set --memory below the memory this machine has free (it bounds the exploration), lower --max-states, or choose a smaller --region";
    if (command == "verify") return "choose a smaller --region or a lower --depth";
    if (command == "plan") return "choose smaller --from/--to shapes or a lower --scale";
    if (command == "hex") return "choose a smaller --size or fewer --steps";
    if (command == "roombots") return "choose a smaller structure or fewer --runs";
    return "give it fewer or smaller files";
}

int runHolon(int argc, char** argv) {
    CLI::App app{"holon: check, verify and run rule systems for lattice modular robots"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "holon 0.1.0");
    std::map<CLI::App*, holon::cli::Run> runs;
    auto add = [&](holon::cli::Run (*factory)(CLI::App&)) {
        const std::size_t before = app.get_subcommands({}).size();
        holon::cli::Run run = factory(app);
        runs[app.get_subcommands({})[before]] = std::move(run);
    };
    add(holon::cli::addRulesCommand);
    add(holon::cli::addCheckCommand);
    add(holon::cli::addVerifyCommand);
    add(holon::cli::addPlanCommand);
    add(holon::cli::addHexCommand);
    add(holon::cli::addRoombotsCommand);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return holon::cli::kExitBadInput;
    }
    std::string command;
    try {
        for (auto& [sub, run] : runs)
            if (sub->parsed()) {
                command = sub->get_name();
                return run();
            }
    } catch (const holon::InputError& e) {
        std::cerr << "holon: error: " << e.what() << '\n';
        return holon::cli::kExitBadInput;
    } catch (const std::bad_alloc&) {
        std::cerr << "holon " << command << ": stopped: the machine has no memory left for this job; " << memoryAdvice(command) << '\n';
        return holon::cli::kExitUndecided;
    } catch (const std::exception& e) {
        std::cerr << "holon: internal error: " << e.what() << "\n  this is a bug in holon, not in your input; please report it with the command line\n";
        return holon::cli::kExitInternal;
    }
    return holon::cli::kExitInternal;
}

}  // namespace

int main(int argc, char** argv) {
    if (!isatty(STDOUT_FILENO)) checkedStdout.install();
    int code = runHolon(argc, argv);
    const std::string lost = stdoutFailure();
    if (!lost.empty()) {
        std::cerr << "holon: error: cannot write standard output: " << lost << '\n';
        // The report of a verdict (0, 1, 3) that did not arrive cannot stand: 2. An internal error
        // (4), bad input (2) or an interrupted run (128 + signal) keeps its own code, which says
        // more about what happened.
        if (code == holon::cli::kExitOk || code == holon::cli::kExitViolated || code == holon::cli::kExitUndecided) code = holon::cli::kExitBadInput;
    }
    return code;
}
