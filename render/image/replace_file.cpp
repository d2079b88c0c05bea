// Atomic, checked replacement of a file (replace_file.hpp). The temporary
// lives in the target's folder (a rename cannot cross file systems) under a
// short name of its own, ".kerf-tmp-PID-N", so a target name of NAME_MAX
// bytes still has a temporary that fits.
#include "render/image/replace_file.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>

#include <fcntl.h>
#include <unistd.h>

namespace kerf::render {

namespace {

// ---- Removing a named temporary when a signal ends the process ----------
//
// A handful of slots, so concurrent writers in one process each get theirs
// (a writer finding none free still works, its temporary just is not
// removed on a signal). The handler only reads lock-free atomics and calls
// unlinkat(), both async-signal-safe.
struct Slot {
    std::atomic<bool> taken{false};
    std::atomic<int> dirfd{-1};  // >= 0 while `name` names a temporary to remove
    char name[64] = {};
};
Slot g_slots[8];
constexpr int kCleanupSignals[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGXFSZ};

void remove_temporaries_and_die(int sig) {
    for (Slot& s : g_slots)
        if (const int dirfd = s.dirfd.load(); dirfd >= 0) ::unlinkat(dirfd, s.name, 0);
    // The default action, as if no handler had run: the exit status still
    // says which signal ended the process.
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);  // blocked in the handler: delivered as it returns
}

void install_cleanup_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int sig : kCleanupSignals) {
            struct sigaction old {};
            // An ignored signal, or one the embedding program handles, stays so.
            if (::sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL)
                continue;
            struct sigaction sa {};
            sa.sa_handler = remove_temporaries_and_die;
            sigemptyset(&sa.sa_mask);
            ::sigaction(sig, &sa, nullptr);
        }
    });
}

// A temporary name in a folder, registered for removal on a signal while it
// exists: between next() (before the file is created) and the destructor
// (after it was renamed or removed).
class TempName {
public:
    explicit TempName(int dirfd) : dirfd_(dirfd) {
        install_cleanup_handlers();
        for (Slot& s : g_slots) {
            bool free = false;
            if (s.taken.compare_exchange_strong(free, true)) {
                slot_ = &s;
                break;
            }
        }
        next();
    }
    ~TempName() { release(); }
    TempName(const TempName&) = delete;
    TempName& operator=(const TempName&) = delete;

    // A fresh name (after EEXIST: a stale temporary of an earlier process
    // with the same id).
    void next() {
        static std::atomic<unsigned> counter{0};
        release_name();
        std::snprintf(name_, sizeof name_, ".kerf-tmp-%ld-%u", static_cast<long>(::getpid()), counter++);
        if (slot_) {
            std::memcpy(slot_->name, name_, sizeof name_);
            slot_->dirfd.store(dirfd_);
        }
    }
    const char* c_str() const { return name_; }

private:
    void release_name() {
        if (slot_) slot_->dirfd.store(-1);
    }
    void release() {
        release_name();
        if (slot_) slot_->taken.store(false);
    }

    int dirfd_;
    Slot* slot_ = nullptr;
    char name_[sizeof Slot::name] = {};
};

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free,
              "the signal handler reads these atomics");

// ---- Checked system calls ---------------------------------------------

struct Fd {
    int fd = -1;
    explicit Fd(int f) : fd(f) {}
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    // close(2) with its result: a deferred write error (NFS) shows here.
    std::string close_checked() {
        const int f = fd;
        fd = -1;
        return ::close(f) == 0 || errno == EINTR ? std::string() : errno_text(errno);
    }
};

// Every byte written (write(2) may take fewer than asked; EINTR is retried),
// then fsync(2): the data is on the device before the rename publishes it.
std::string write_all_and_sync(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    for (std::size_t done = 0; done < size;) {
        const ssize_t n = ::write(fd, p + done, std::min<std::size_t>(size - done, std::size_t(1) << 30));
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno_text(errno);
        }
        if (n == 0) return "the file system took no more bytes";
        done += static_cast<std::size_t>(n);
    }
    return ::fsync(fd) == 0 ? std::string() : errno_text(errno);
}

// The folder a target lives in, opened for the *at() calls, and the
// target's name inside it.
struct Folder {
    Fd dir{-1};
    std::string leaf;
    std::string error;
    explicit Folder(const std::string& target) {
        const std::filesystem::path t(target);
        leaf = t.filename().string();
        const std::string folder = t.parent_path().empty() ? "." : t.parent_path().string();
        dir.fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (dir.fd < 0) error = errno_text(errno);
    }
};

// O_TMPFILE is missing from this file system (or kernel): use a named file.
bool tmpfile_unsupported(int err) { return err == EOPNOTSUPP || err == EISDIR || err == EINVAL; }

int open_anonymous(int dirfd) { return ::openat(dirfd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666); }

// Creates `name` exclusively, choosing another name while it exists.
int create_named(int dirfd, TempName& name) {
    for (int attempt = 0;; ++attempt, name.next()) {
        const int fd = ::openat(dirfd, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST || attempt == 100) return fd;
    }
}

// Gives the anonymous file `fd` a name. False (errno set) when linking is
// not possible here: no /proc, or a file system that refuses.
bool link_anonymous(int fd, int dirfd, TempName& name) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    for (int attempt = 0;; ++attempt, name.next()) {
        if (::linkat(AT_FDCWD, self.c_str(), dirfd, name.c_str(), AT_SYMLINK_FOLLOW) == 0) return true;
        if (errno != EEXIST || attempt == 100) return false;
    }
}

// The last step: the temporary takes the target's place; on failure it goes.
std::string rename_over(const Folder& f, const TempName& name) {
    if (::renameat(f.dir.fd, name.c_str(), f.dir.fd, f.leaf.c_str()) != 0) {
        const std::string why = errno_text(errno);
        ::unlinkat(f.dir.fd, name.c_str(), 0);
        return why;
    }
    // Makes the rename itself durable. Best effort: some file systems
    // refuse fsync on folders, and the new file is in place either way.
    ::fsync(f.dir.fd);
    return {};
}

}  // namespace

std::string errno_text(int err) {
    std::string s = std::strerror(err);
    if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

std::string replace_file(const std::string& target, const void* data, std::size_t size) {
    const Folder folder(target);
    if (!folder.error.empty()) return folder.error;
    const int dirfd = folder.dir.fd;
    {
        Fd anon(open_anonymous(dirfd));
        if (anon.fd < 0 && !tmpfile_unsupported(errno)) return errno_text(errno);
        if (anon.fd >= 0) {
            if (std::string why = write_all_and_sync(anon.fd, data, size); !why.empty()) return why;
            TempName name(dirfd);
            if (link_anonymous(anon.fd, dirfd, name)) {
                if (std::string why = anon.close_checked(); !why.empty()) {
                    ::unlinkat(dirfd, name.c_str(), 0);
                    return why;
                }
                return rename_over(folder, name);
            }
            // Cannot be linked: write the bytes again, under a name.
        }
    }
    TempName name(dirfd);
    Fd named(create_named(dirfd, name));
    if (named.fd < 0) return errno_text(errno);
    std::string why = write_all_and_sync(named.fd, data, size);
    if (why.empty()) why = named.close_checked();
    if (why.empty()) return rename_over(folder, name);
    ::unlinkat(dirfd, name.c_str(), 0);
    return why;
}

std::string probe_folder(const std::string& target) {
    const Folder folder(target);
    if (!folder.error.empty()) return folder.error;
    Fd anon(open_anonymous(folder.dir.fd));
    if (anon.fd >= 0) return {};
    if (!tmpfile_unsupported(errno)) return errno_text(errno);
    TempName name(folder.dir.fd);
    Fd named(create_named(folder.dir.fd, name));
    if (named.fd < 0) return errno_text(errno);
    ::unlinkat(folder.dir.fd, name.c_str(), 0);
    return {};
}

}  // namespace kerf::render
