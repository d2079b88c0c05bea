// kerf as a child process the test controls, for what run_kerf (a shell
// that waits) cannot do: signal kerf in the middle of writing its image, or
// run it as on a file system without O_TMPFILE. Linux only, like kerf's
// file replacement itself.
#pragma once
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

// In the child, before exec: openat() with O_TMPFILE fails with EOPNOTSUPP,
// as on a file system that lacks it, so kerf takes its named-temporary path.
// (The kernel's __O_TMPFILE bit alone: glibc's macro includes O_DIRECTORY.)
inline bool refuse_tmpfile_in_child() {
#if defined(__x86_64__)
    constexpr unsigned kTmpfileBit = 020000000;
    struct sock_filter filter[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, arch)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_openat, 0, 3),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, args[2])),  // flags, low word
        BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, kTmpfileBit, 0, 1),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | (EOPNOTSUPP & SECCOMP_RET_DATA)),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    };
    struct sock_fprog prog = {static_cast<unsigned short>(sizeof filter / sizeof filter[0]), filter};
    return ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && ::prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &prog) == 0;
#else
    return false;
#endif
}

struct SpawnOptions {
    bool without_tmpfile = false;  // see refuse_tmpfile_in_child
    std::string stderr_path = "/dev/null";
};

// Starts KERF_BINARY_DIR/kerf with `args` (no shell, so the pid is kerf's),
// with SIGINT and SIGTERM at their default action whatever the test runner
// set. Returns the pid, or -1.
inline pid_t spawn_kerf(const std::vector<std::string>& args, const SpawnOptions& options = {}) {
    const std::string exe = std::string(KERF_BINARY_DIR) + "/kerf";
    std::vector<std::string> all{exe};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid != 0) return pid;
    // The child: only async-signal-safe calls until exec.
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open("/dev/null", O_WRONLY);
    const int err = ::open(options.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (options.without_tmpfile && !refuse_tmpfile_in_child()) ::_exit(125);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
}

// Exit status as run_kerf reports it: the code, or 128 + the signal.
inline int status_of(int raw) { return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw); }

inline int wait_kerf(pid_t pid) {
    int raw = 0;
    while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
    }
    return status_of(raw);
}

// The descriptor of `pid` open on a file in `dir` that is not in place yet
// (an anonymous O_TMPFILE file, "/dir/#123 (deleted)", or a name holding
// "kerf-tmp") and already holds bytes: the image being written. Empty if none.
inline std::string writing_fd(pid_t pid, const std::filesystem::path& dir) {
    std::error_code ec;
    const std::string prefix = dir.string() + "/";
    for (const auto& e : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
        const std::string link = std::filesystem::read_symlink(e.path(), ec).string();
        if (ec || link.rfind(prefix, 0) != 0) continue;
        const bool anonymous = link.size() > 10 && link.compare(link.size() - 10, 10, " (deleted)") == 0;
        if (!anonymous && link.find("kerf-tmp") == std::string::npos) continue;
        struct stat st {};
        if (::stat(e.path().c_str(), &st) == 0 && st.st_size > 0) return e.path().string();
    }
    return {};
}

// Polls until kerf is writing its image into `dir`, then stops it there
// (SIGSTOP) with the temporary still open and not renamed. False if kerf
// exited first (its status is then collected into `status`) or, when
// `seconds` is given, still runs without having been caught by then
// (`status` stays as it was).
inline bool stop_while_writing(pid_t pid, const std::filesystem::path& dir, int& status, double seconds = -1) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (seconds < 0 || std::chrono::steady_clock::now() < end) {
        if (!writing_fd(pid, dir).empty()) {
            ::kill(pid, SIGSTOP);
            int raw = 0;
            ::waitpid(pid, &raw, WUNTRACED);
            if (WIFSTOPPED(raw) && !writing_fd(pid, dir).empty()) return true;
            if (!WIFSTOPPED(raw)) {
                status = status_of(raw);
                return false;
            }
            ::kill(pid, SIGCONT);  // stopped just after the rename: too late, look again
        }
        int raw = 0;
        const pid_t done = ::waitpid(pid, &raw, WNOHANG);
        if (done == pid) {
            status = status_of(raw);
            return false;
        }
        ::usleep(100);
    }
    return false;
}
