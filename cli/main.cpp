// The `holon` command: one binary, a subcommand per job. Exit codes are the same for every
// subcommand (cli/Commands.h): 0 success, 1 a checked property does not hold, 2 bad input or
// usage, 3 undecided, 4 an internal error. Standard output is checked at the end: a report that
// did not reach its reader (a full disk, /dev/full) is an error, not a success.

#include "cli/Commands.h"
#include "rules/Error.h"
#include "rules/Escape.h"

#include "rules/StopSignals.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
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

}  // namespace

int main(int argc, char** argv) {
    holon::rules::endOnSignalsCleanly();
    if (!isatty(STDOUT_FILENO)) checkedStdout.install();
    int code = holon::cli::runHolon(argc, argv);
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
