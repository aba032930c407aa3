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
#include <istream>
#include <memory>
#include <poll.h>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace holon::rules {

namespace {

/// Waits until `fd` has data or its writer has gone, a slice at a time.
void waitReadable(int fd, const std::string& path) {
    for (;;) {
        StopSignals::checkJob("holon waited for '" + path + "' (a pipe or FIFO that nothing wrote); start its writer first, or raise the limit");
        const double left = jobSecondsLeft();
        pollfd polled{fd, POLLIN, 0};
        const int slice = static_cast<int>(std::ceil(std::min(left, 0.1) * 1000));
        const int ready = ::poll(&polled, 1, slice);
        if (ready > 0) return;
        if (ready < 0 && errno != EINTR) throw InputError("cannot read '" + path + "': waiting for it failed");
    }
}

/// An input file opened without blocking (opening a FIFO does not wait for its writer), read a
/// piece at a time, waiting for a pipe or FIFO in slices.
class InputFile {
public:
    explicit InputFile(const std::string& path) : path_(path) {
        std::error_code error;
        if (std::filesystem::is_directory(path, error)) throw InputError("cannot read '" + path + "': it is a folder, not a file");
        while ((fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)) < 0 && errno == EINTR) StopSignals::stopIfCaught();
        if (fd_ < 0) throw InputError("cannot read '" + path + "': no such file or not readable");
        struct stat status {};
        mayWait_ = ::fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode);
    }
    ~InputFile() { ::close(fd_); }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    /// Up to `size` bytes into `to`; 0 at the end of the file.
    std::size_t read(char* to, std::size_t size) {
        for (;;) {
            if (mayWait_) waitReadable(fd_, path_);
            const ssize_t got = ::read(fd_, to, size);
            if (got >= 0) return static_cast<std::size_t>(got);
            if (errno != EINTR && errno != EAGAIN) throw InputError("cannot read '" + path_ + "': a read error");
            StopSignals::stopIfCaught();
        }
    }

private:
    std::string path_;
    int fd_ = -1;
    bool mayWait_ = false;
};

/// A stream over an InputFile, for inputs read line by line (a plan of millions of lines).
class InputStreamBuf : public std::streambuf {
public:
    explicit InputStreamBuf(const std::string& path) : file_(path), buffer_(1 << 16) {}

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        const std::size_t got = file_.read(buffer_.data(), buffer_.size());
        if (got == 0) return traits_type::eof();
        setg(buffer_.data(), buffer_.data(), buffer_.data() + got);
        return traits_type::to_int_type(*gptr());
    }

private:
    InputFile file_;
    std::vector<char> buffer_;
};

class InputStream : public std::istream {
public:
    explicit InputStream(const std::string& path) : std::istream(nullptr), buf_(path) {
        rdbuf(&buf_);
        // A stream swallows what its buffer throws (the deadline, a signal) and sets badbit, and a
        // reader that peeks again spun at full speed: with badbit in the mask it is thrown on.
        exceptions(std::ios::badbit);
    }

private:
    InputStreamBuf buf_;
};

}  // namespace

std::unique_ptr<std::istream> openInputStream(const std::string& path) { return std::make_unique<InputStream>(path); }

std::string readTextFile(const std::string& path, std::size_t maxBytes) {
    InputFile file(path);
    std::string text;
    std::vector<char> buffer(1 << 16);
    for (;;) {
        const std::size_t got = file.read(buffer.data(), buffer.size());
        if (got == 0) break;
        text.append(buffer.data(), got);
        if (text.size() > maxBytes)
            throw InputError("'" + path + "' is larger than " + std::to_string(maxBytes >> 20) +
                             " MiB, the most holon reads from such a file; is it the right file?");
    }
    return text;
}

}  // namespace holon::rules
