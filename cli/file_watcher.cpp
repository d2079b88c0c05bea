#include "cli/file_watcher.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

// Written in place (modify, close), replaced (moved or created over),
// removed or renamed away, touched.
constexpr std::uint32_t kEvents = IN_MODIFY | IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE |
                                  IN_DELETE | IN_ATTRIB | IN_ONLYDIR;

// (folder, name) of `path`, the folder absolute so that one folder spelt
// two ways gets one watch.
std::pair<std::string, std::string> split(const fs::path& path) {
    std::error_code ec;
    fs::path abs = fs::absolute(path, ec);
    if (ec) abs = path;
    abs = abs.lexically_normal();
    return {abs.parent_path().string(), abs.filename().string()};
}

}  // namespace

FileWatcher::FileWatcher() : fd_(::inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
    if (fd_ < 0) throw std::runtime_error(std::string("cannot watch files: inotify: ") + std::strerror(errno));
}

FileWatcher::~FileWatcher() { ::close(fd_); }

void FileWatcher::watch(const std::vector<std::string>& paths) {
    std::map<std::string, std::map<std::string, std::string>> wanted;
    for (const std::string& p : paths) {
        const auto [dir, name] = split(p);
        wanted[dir].emplace(name, p);
        std::error_code ec;
        if (fs::is_symlink(p, ec)) {  // edits land on the target
            const auto [target_dir, target_name] = split(fs::weakly_canonical(p, ec));
            if (!ec) wanted[target_dir].emplace(target_name, p);
        }
    }
    for (auto it = dirs_.begin(); it != dirs_.end();) {
        if (!wanted.count(it->second)) {
            ::inotify_rm_watch(fd_, it->first);
            it = dirs_.erase(it);
        } else {
            ++it;
        }
    }
    for (const auto& [dir, names] : wanted) {
        bool have = false;
        for (const auto& [wd, d] : dirs_) have = have || d == dir;
        if (have) continue;
        const int wd = ::inotify_add_watch(fd_, dir.c_str(), kEvents);
        if (wd >= 0) dirs_[wd] = dir;
    }
    names_ = std::move(wanted);
}

bool FileWatcher::read_events() {
    alignas(inotify_event) char buf[16384];
    bool relevant = false;
    for (;;) {
        const ssize_t n = ::read(fd_, buf, sizeof buf);
        if (n <= 0) return relevant;  // EAGAIN: the queue is empty
        for (ssize_t at = 0; at < n;) {
            const auto* e = reinterpret_cast<const inotify_event*>(buf + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
            if (e->mask & IN_Q_OVERFLOW) {  // events were lost: assume the worst
                if (changed_.empty()) changed_ = "a watched file";
                relevant = true;
                continue;
            }
            if (e->mask & IN_IGNORED) {  // the folder went away; watch() adds it again
                dirs_.erase(e->wd);
                continue;
            }
            const auto dir = dirs_.find(e->wd);
            if (dir == dirs_.end() || e->len == 0) continue;
            const auto names = names_.find(dir->second);
            if (names == names_.end()) continue;
            const auto name = names->second.find(e->name);
            if (name == names->second.end()) continue;
            if (changed_.empty()) changed_ = name->second;
            relevant = true;
        }
    }
}

bool FileWatcher::wait(int timeout_ms) {
    using clock = std::chrono::steady_clock;
    const auto end = clock::now() + std::chrono::milliseconds(timeout_ms);
    for (;;) {
        int left = -1;
        if (timeout_ms >= 0) {
            left = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(end - clock::now()).count());
            if (left < 0) left = 0;
        }
        pollfd p{fd_, POLLIN, 0};
        const int r = ::poll(&p, 1, left);
        if (r < 0 && errno != EINTR) throw std::runtime_error(std::string("cannot watch files: poll: ") + std::strerror(errno));
        if (r > 0 && read_events()) return true;
        if (r == 0 && left == 0) return false;
    }
}

void FileWatcher::settle(int quiet_ms, int longest_ms) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(longest_ms);
    while (std::chrono::steady_clock::now() < end) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now()).count();
        if (!wait(static_cast<int>(std::min<long long>(quiet_ms, std::max<long long>(left, 0))))) return;
    }
}

}  // namespace kerf::cli
