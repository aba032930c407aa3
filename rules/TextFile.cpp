// The one reader of whole input files (rules/TextFile.h). POSIX reads rather than a stream, so that
// a file that keeps holon waiting (a pipe or FIFO with no writer yet, a terminal) is waited for in
// slices: SIGINT or SIGTERM stops the job as an interrupt (130, 143), not as a file that cannot be
// read (2), and --timeout, which counts from the job's start, holds while it waits (exit 3).

#include "rules/TextFile.h"

#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/StopSignals.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace holon::rules {

namespace {

/// Waits until `fd` has data or its writer has gone, a slice at a time.
void waitReadable(int fd, const std::string& path) {
    for (;;) {
        StopSignals::stopIfCaught();
        checkJobDeadline("holon waited for '" + path + "' (a pipe or FIFO that nothing wrote); start its writer first, or raise the limit");
        const double left = jobSecondsLeft();
        pollfd polled{fd, POLLIN, 0};
        const int slice = static_cast<int>(std::ceil(std::min(left, 0.1) * 1000));
        const int ready = ::poll(&polled, 1, slice);
        if (ready > 0) return;
        if (ready < 0 && errno != EINTR) throw InputError("cannot read '" + path + "': waiting for it failed");
    }
}

}  // namespace

std::string readTextFile(const std::string& path, std::size_t maxBytes) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw InputError("cannot read '" + path + "': it is a folder, not a file");
    // Non-blocking, so that opening a FIFO does not wait for its writer (the wait is below).
    int fd = -1;
    while ((fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)) < 0 && errno == EINTR) StopSignals::stopIfCaught();
    if (fd < 0) throw InputError("cannot read '" + path + "': no such file or not readable");
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat status {};
    const bool mayWait = ::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode);
    std::string text;
    std::vector<char> buffer(1 << 16);
    for (;;) {
        if (mayWait) waitReadable(fd, path);
        const ssize_t got = ::read(fd, buffer.data(), buffer.size());
        if (got == 0) break;
        if (got < 0) {
            if (errno != EINTR && errno != EAGAIN) throw InputError("cannot read '" + path + "': a read error");
            StopSignals::stopIfCaught();
            continue;
        }
        text.append(buffer.data(), static_cast<std::size_t>(got));
        if (text.size() > maxBytes)
            throw InputError("'" + path + "' is larger than " + std::to_string(maxBytes >> 20) +
                             " MiB, the most holon reads from such a file; is it the right file?");
    }
    return text;
}

}  // namespace holon::rules
