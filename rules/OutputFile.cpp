// The checked writer (OutputFile.h). A file is written to "<path>.tmp-XXXXXX" in the same folder,
// flushed and closed with every error checked, then renamed over the path: rename within a folder
// is atomic on POSIX, so a reader (or a job killed half-way) sees the old file or the new one,
// never a torn one. Paths that are not regular files (devices, pipes) cannot be renamed over and
// are written directly.

#include "rules/OutputFile.h"

#include "rules/Error.h"
#include "rules/StopSignals.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fnmatch.h>
#include <mutex>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace holon::rules {

namespace {

namespace fs = std::filesystem;

std::string reason() { return std::strerror(errno); }

/// Opens a device, pipe or FIFO for writing. A FIFO with no reader yet is waited for in slices:
/// a blocking open waited for ever, past --timeout, and a signal read as "cannot open" (exit 2).
int openSpecial(const std::string& option, const std::string& path) {
    for (;;) {
        const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_NONBLOCK | O_CLOEXEC);
        if (fd >= 0) {
            ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // writes wait for a slow reader
            return fd;
        }
        if (errno != ENXIO && errno != EINTR) throw InputError(option + " " + path + ": cannot open: " + reason());
        StopSignals::checkJob("holon waited for a reader of " + option + " " + path + " (a FIFO nothing reads); start its reader first, or raise the limit");
        ::usleep(50'000);
    }
}

std::string folderOf(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

bool isSpecial(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

/// Writes all of `text` to `fd`; false (with errno set) on any error. A write blocked on a pipe
/// nobody reads ends at a caught SIGINT or SIGTERM (EINTR; commit() then says Interrupted): it
/// retried for ever, deaf to them.
bool writeAll(int fd, std::string_view text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR && *StopSignals::caught() == 0) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

namespace {

/// The temporaries being written now, for removeTemporaries: fixed buffers and lock-free flags, so
/// a signal handler can read them (unlink is async-signal-safe; nothing here allocates).
constexpr int kTemporaries = 32;
char temporaryPaths[kTemporaries][4096];
std::atomic<bool> temporaryInUse[kTemporaries];
std::mutex temporaryLock;  // between threads that start or finish writing; never taken in a handler

/// Registers a temporary; -1 when the table is full or the path too long (then it is not removed
/// on a signal, only on an error).
int trackTemporary(const std::string& path) {
    const std::lock_guard<std::mutex> hold(temporaryLock);
    for (int k = 0; k < kTemporaries; ++k)
        if (!temporaryInUse[k].load() && path.size() < sizeof temporaryPaths[k]) {
            std::memcpy(temporaryPaths[k], path.c_str(), path.size() + 1);
            temporaryInUse[k].store(true);
            return k;
        }
    return -1;
}

void untrackTemporary(int k) {
    if (k >= 0) temporaryInUse[k].store(false);
}

/// The paths claimed while an OutputClaims lives: a file or folder, the option that names it, and
/// whether it is a folder (whose files belong to that option) or an input (nothing may replace it).
struct Claim {
    fs::path path;
    std::string option;
    enum class Kind { File,
                      Folder,
                      Input } kind;
    bool created = false;            // a folder this job made: removed at the end if it stays empty
    std::vector<std::string> names;  // a folder's files, if declared (patterns); empty: all of it
};
std::vector<Claim>* claims = nullptr;

fs::path canonicalOf(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::path(path).lexically_normal() : p;
}

bool inside(const fs::path& file, const fs::path& folder) {
    const auto [f, d] = std::mismatch(file.begin(), file.end(), folder.begin(), folder.end());
    return d == folder.end() && f != file.end();
}

/// Whether `folder`'s option writes `file` (which lies inside it): any file, unless it declared
/// the names it writes.
bool writes(const Claim& folder, const fs::path& file) {
    if (folder.names.empty()) return true;
    const std::string relative = file.lexically_relative(folder.path).string();
    return std::any_of(folder.names.begin(), folder.names.end(), [&](const std::string& name) { return ::fnmatch(name.c_str(), relative.c_str(), FNM_PATHNAME) == 0; });
}

void claim(const std::string& option, const std::string& path, Claim::Kind kind, const std::vector<std::string>& names = {}) {
    if (!claims) return;
    // Reading a terminal or a pipe replaces nothing (a configuration typed at the terminal while
    // --svg writes /dev/stdout resolved to one /dev/pts/N and was refused).
    if (kind == Claim::Kind::Input && isSpecial(path)) return;
    const fs::path p = canonicalOf(path);
    const Claim made{p, option, kind, false, names};
    for (const Claim& c : *claims) {
        if (kind == Claim::Kind::Input && c.kind == Claim::Kind::Input) continue;  // a file read twice, or as two inputs
        const bool same = c.path == p, within = c.kind == Claim::Kind::Folder && kind != Claim::Kind::Folder && inside(p, c.path) && writes(c, p);
        if ((same && c.kind == Claim::Kind::Input) || (same && kind == Claim::Kind::Input && c.kind != Claim::Kind::Folder))
            throw InputError(option + " " + path + ": is also " + (c.kind == Claim::Kind::Input ? "read as " : "written as ") + c.option + "; name another file");
        if (c.option == option) continue;  // one option writing a file twice, or its own folder's files
        if (same) throw InputError(option + " " + path + ": " + c.option + " writes there too; give each output its own " + (kind == Claim::Kind::Folder ? "folder" : "file"));
        if (within)
            throw InputError(option + " " + path + (c.names.empty() ? ": lies in the folder " + c.option + " writes; name a file outside it" : ": " + c.option + " writes a file of that name in its folder; name another file"));
        if (kind == Claim::Kind::Folder && c.kind != Claim::Kind::Folder && inside(c.path, p) && writes(made, c.path))
            throw InputError(option + " " + path + ": holds " + c.option + "'s file " + c.path.string() + "; name another folder");
    }
    claims->push_back(made);
}

}  // namespace

OutputClaims::OutputClaims() {
    if (claims) throw InternalError("OutputClaims: one job at a time");
    claims = new std::vector<Claim>();
}

OutputClaims::~OutputClaims() {
    // A folder the job made and wrote nothing into (a refused, failed or interrupted job) is
    // removed: outputs are complete or absent. rmdir removes only an empty folder.
    for (const Claim& c : *claims)
        if (c.created) ::rmdir(c.path.c_str());
    delete claims;
    claims = nullptr;
}

void OutputClaims::reading(const std::string& option, const std::string& path) { claim(option, path, Claim::Kind::Input); }

OutputFile::OutputFile(std::string option, std::string path) : option_(std::move(option)), path_(std::move(path)) {
    if (path_.empty()) throw InputError(option_ + ": the path is empty; name a file");
    claim(option_, path_, Claim::Kind::File);
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw InputError(option_ + " " + path_ + ": is a folder; name a file inside it");
    if (isSpecial(path_)) {
        if (::access(path_.c_str(), W_OK) != 0) throw InputError(option_ + " " + path_ + ": cannot write: " + reason());
        return;
    }
    const std::string folder = folderOf(path_);
    if (::stat(folder.c_str(), &st) != 0) throw InputError(option_ + " " + path_ + ": the folder '" + folder + "' does not exist; create it first");
    if (!S_ISDIR(st.st_mode)) throw InputError(option_ + " " + path_ + ": '" + folder + "' is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0) throw InputError(option_ + " " + path_ + ": cannot write into '" + folder + "': " + reason());
}

// One way to write a file, whole or in pieces: the stream's temporary, checks and rename.
void OutputFile::write(const std::string& text) const {
    write([&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

void OutputFile::write(const std::function<void(std::ostream&)>& fill) const {
    OutputStream s = open();
    fill(s.stream());
    s.commit();
}

/// Buffers what is streamed and writes it to the descriptor in large pieces, keeping errno of the
/// first write that failed; later writes are dropped.
struct OutputStream::Buffer : std::streambuf {
    int fd;
    int error = 0;
    std::vector<char> space = std::vector<char>(std::size_t{1} << 16);

    explicit Buffer(int descriptor) : fd(descriptor) { setp(space.data(), space.data() + space.size()); }
    ~Buffer() override {
        if (fd >= 0) ::close(fd);
    }
    bool drain() {
        if (!error && pptr() > pbase() && !writeAll(fd, std::string_view(pbase(), static_cast<std::size_t>(pptr() - pbase())))) error = errno ? errno : EIO;
        setp(space.data(), space.data() + space.size());
        return error == 0;
    }
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) *pptr() = traits_type::to_char_type(c), pbump(1);
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }
    // A piece larger than the buffer (a whole file given at once) goes straight to the descriptor.
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        if (static_cast<std::size_t>(n) < space.size()) return std::streambuf::xsputn(s, n);
        if (!drain()) return 0;
        if (!writeAll(fd, std::string_view(s, static_cast<std::size_t>(n)))) {
            error = errno ? errno : EIO;
            return 0;
        }
        return n;
    }
};

OutputStream::OutputStream(std::string option, std::string path) : option_(std::move(option)), path_(std::move(path)) {
    int fd = -1;
    if (isSpecial(path_)) {
        fd = openSpecial(option_, path_);
    } else {
        temp_ = path_ + ".tmp-XXXXXX";
        fd = ::mkstemp(temp_.data());
        if (fd < 0) throw InputError(option_ + " " + path_ + ": cannot create a file beside it: " + reason());
        tracked_ = trackTemporary(temp_);
    }
    try {
        buffer_ = std::make_unique<Buffer>(fd);
    } catch (...) {
        ::close(fd);
        if (!temp_.empty()) ::unlink(temp_.c_str());
        untrackTemporary(std::exchange(tracked_, -1));
        throw;
    }
    out_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputStream::OutputStream(OutputStream&& o) noexcept
    : option_(std::move(o.option_)), path_(std::move(o.path_)), temp_(std::exchange(o.temp_, {})), buffer_(std::move(o.buffer_)), out_(std::move(o.out_)),
      committed_(o.committed_), tracked_(std::exchange(o.tracked_, -1)) {}  // the moved-from one no longer names the temporary it would remove

OutputStream::~OutputStream() {
    if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
    untrackTemporary(tracked_);
}

void OutputStream::commit() {
    out_->flush();
    bool ok = buffer_->drain() && !out_->fail();
    int error = buffer_->error;
    if (ok && !temp_.empty() && ::fsync(buffer_->fd) != 0) ok = false, error = errno;
    if (::close(buffer_->fd) != 0 && ok) ok = false, error = errno;
    buffer_->fd = -1;
    if (!ok) {
        if (error == EINTR) StopSignals::stopIfCaught();
        errno = error ? error : EIO;
        throw InputError(option_ + " " + path_ + ": cannot write: " + reason());
    }
    if (!temp_.empty()) {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        ::chmod(temp_.c_str(), 0666 & ~mask);
        if (::rename(temp_.c_str(), path_.c_str()) != 0)
            throw InputError(option_ + " " + path_ + ": cannot move the finished file into place: " + reason());
    }
    committed_ = true;
    untrackTemporary(std::exchange(tracked_, -1));
}

void removeTemporaries() noexcept {
    for (int k = 0; k < kTemporaries; ++k)
        if (temporaryInUse[k].load()) ::unlink(temporaryPaths[k]);
}

void removeEarlierOutputs(const std::string& dir, const std::vector<std::string>& names) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file(ec) && std::any_of(names.begin(), names.end(), [&](const std::string& n) { return ::fnmatch(n.c_str(), name.c_str(), FNM_PATHNAME) == 0; }))
            fs::remove(entry.path(), ec);
    }
}

void prepareOutputDir(const std::string& option, const std::string& dir, const std::vector<std::string>& names) {
    if (dir.empty()) throw InputError(option + ": the folder name is empty");
    claim(option, dir, Claim::Kind::Folder, names);
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0) {
        if (!S_ISDIR(st.st_mode)) throw InputError(option + " " + dir + ": exists and is not a folder; name a folder");
    } else {
        // Only the folder itself is created: a mistyped parent is refused rather than silently
        // starting a new tree of folders somewhere else.
        const fs::path normal = fs::path(dir).lexically_normal();
        const fs::path up = (normal.has_filename() ? normal : normal.parent_path()).parent_path();
        const std::string folder = up.empty() ? "." : up.string();
        if (::stat(folder.c_str(), &st) != 0) throw InputError(option + " " + dir + ": the folder '" + folder + "' does not exist; create it first");
        if (!S_ISDIR(st.st_mode)) throw InputError(option + " " + dir + ": '" + folder + "' is not a folder");
        if (::mkdir(dir.c_str(), 0777) == 0) {
            if (claims) claims->back().created = true;  // claimed just above
        } else if (errno != EEXIST) {
            throw InputError(option + " " + dir + ": cannot create the folder: " + reason());
        }
    }
    if (::access(dir.c_str(), W_OK | X_OK) != 0) throw InputError(option + " " + dir + ": cannot write into the folder: " + reason());
}

}  // namespace holon::rules
