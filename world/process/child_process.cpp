#include "world/process/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <thread>

#include "world/error.hpp"

extern char** environ;

namespace onelight::world {
namespace {

using Clock = std::chrono::steady_clock;

/// A pipe whose ends are closed with it; both ends are close-on-exec, so no other child started
/// meanwhile inherits them (the child's own copies are made by dup2, which clears the flag).
struct Pipe {
    int fd[2] = {-1, -1};
    explicit Pipe(const std::string& program) {
        if (pipe2(fd, O_CLOEXEC) != 0)
            throw Error(program + ": cannot create a pipe to run it (" + std::strerror(errno) +
                        ")");
    }
    ~Pipe() {
        closeEnd(0);
        closeEnd(1);
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;
    void closeEnd(int end) {
        if (fd[end] >= 0) close(fd[end]);
        fd[end] = -1;
    }
};

/// posix_spawn's file actions and attributes, destroyed with it.
struct SpawnSetup {
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attributes;
    SpawnSetup() {
        posix_spawn_file_actions_init(&actions);
        posix_spawnattr_init(&attributes);
    }
    ~SpawnSetup() {
        posix_spawnattr_destroy(&attributes);
        posix_spawn_file_actions_destroy(&actions);
    }
    SpawnSetup(const SpawnSetup&) = delete;
    SpawnSetup& operator=(const SpawnSetup&) = delete;
};

/// Sends the stream `target` (1 or 2) where `how` says; `pipeEnd` is the write end when captured.
void routeStream(SpawnSetup& setup, int target, ChildStream how, int pipeEnd) {
    switch (how) {
        case ChildStream::kCapture:
            posix_spawn_file_actions_adddup2(&setup.actions, pipeEnd, target);
            break;
        case ChildStream::kDiscard:
            posix_spawn_file_actions_addopen(&setup.actions, target, "/dev/null", O_WRONLY, 0);
            break;
        case ChildStream::kIntoStdout:
            posix_spawn_file_actions_adddup2(&setup.actions, STDOUT_FILENO, target);
            break;
        case ChildStream::kInherit:
            break;
    }
}

/// Waits for `pid`, retrying when a signal interrupts the wait; returns its status.
int waitForExit(pid_t pid, const std::string& program) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            throw Error(program + ": cannot wait for it (" + std::strerror(errno) + ")");
    return status;
}

/// Writes all of `text` to `fd`, retrying when interrupted.
void writeAll(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += size_t(n);
    }
}

/// Puts the reason a program could not be run where its stderr would have gone, as a shell does.
void reportNotStarted(ChildResult& result, const ChildOptions& options, const std::string& why) {
    const ChildStream where = options.err == ChildStream::kIntoStdout ? options.out : options.err;
    const bool toStdout = options.err == ChildStream::kIntoStdout;
    if (where == ChildStream::kCapture)
        (toStdout ? result.out : result.err) += why;
    else if (where == ChildStream::kInherit)
        writeAll(toStdout ? STDOUT_FILENO : STDERR_FILENO, why);
}

/// Kills the child, or its whole process group when it leads one.
void killChild(pid_t pid, const ChildOptions& options) {
    ::kill(options.killProcessGroup ? -pid : pid, SIGKILL);
}

/// Reads the captured streams until both end or the deadline passes; false at the deadline.
bool readUntilClosed(Pipe* pipes[2], std::string* sinks[2], bool limited,
                     Clock::time_point deadline, const std::string& program) {
    pollfd fds[2];
    int open = 0;
    for (int i = 0; i < 2; ++i) {
        fds[i] = {pipes[i] ? pipes[i]->fd[0] : -1, POLLIN, 0};  // poll skips negative fds
        if (pipes[i]) ++open;
    }
    char buffer[65536];
    while (open > 0) {
        int waitMs = -1;
        if (limited) {
            const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
            if (left <= 0.0) return false;
            waitMs = int(std::ceil(left * 1000.0));
        }
        const int ready = poll(fds, 2, waitMs);
        if (ready < 0) {
            if (errno == EINTR) continue;
            throw Error(program + ": cannot read its output (poll: " + std::strerror(errno) + ")");
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || fds[i].revents == 0) continue;
            const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                sinks[i]->append(buffer, size_t(n));
            } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
                pipes[i]->closeEnd(0);
                fds[i].fd = -1;
                --open;
            }
        }
    }
    return true;
}

/// Waits for `pid` until the deadline; false at the deadline (the child still running).
bool waitUntil(pid_t pid, int& status, bool limited, Clock::time_point deadline,
               const std::string& program) {
    if (!limited) {
        status = waitForExit(pid, program);
        return true;
    }
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) return true;
        if (done < 0 && errno != EINTR)
            throw Error(program + ": cannot wait for it (" + std::strerror(errno) + ")");
        if (Clock::now() >= deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

}  // namespace

ChildResult runChild(const std::vector<std::string>& argv, const ChildOptions& options) {
    if (argv.empty() || argv[0].empty()) throw Error("runChild: no program to run");
    const std::string& program = argv[0];
    if (options.out == ChildStream::kIntoStdout)
        throw Error(program + ": stdout cannot go into stdout; kIntoStdout is for stderr");

    std::unique_ptr<Pipe> outPipe, errPipe;
    if (options.out == ChildStream::kCapture) outPipe = std::make_unique<Pipe>(program);
    if (options.err == ChildStream::kCapture) errPipe = std::make_unique<Pipe>(program);

    SpawnSetup setup;
    posix_spawn_file_actions_addopen(&setup.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    routeStream(setup, STDOUT_FILENO, options.out, outPipe ? outPipe->fd[1] : -1);
    routeStream(setup, STDERR_FILENO, options.err, errPipe ? errPipe->fd[1] : -1);
    // The child starts with no signal blocked and SIGPIPE at its default (this process may
    // ignore it), whatever this process does with its own.
    sigset_t none, pipeSignal;
    sigemptyset(&none);
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    posix_spawnattr_setsigmask(&setup.attributes, &none);
    posix_spawnattr_setsigdefault(&setup.attributes, &pipeSignal);
    short flags = POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF;
    if (options.killProcessGroup) {
        posix_spawnattr_setpgroup(&setup.attributes, 0);
        flags |= POSIX_SPAWN_SETPGROUP;
    }
    posix_spawnattr_setflags(&setup.attributes, flags);

    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);

    ChildResult result;
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, program.c_str(), &setup.actions, &setup.attributes,
                                     args.data(), environ);
    if (spawned != 0) {
        if (spawned == EAGAIN || spawned == ENOMEM)
            throw Error(program + ": cannot start a process to run it (" + std::strerror(spawned) +
                        ")");
        result.started = false;
        result.exitCode = 127;
        reportNotStarted(result, options,
                         program + ": cannot run it (" + std::strerror(spawned) + ")\n");
        return result;
    }
    if (outPipe) outPipe->closeEnd(1);
    if (errPipe) errPipe->closeEnd(1);

    const bool limited = options.timeLimitSeconds > 0.0;
    const Clock::time_point deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(limited ? options.timeLimitSeconds : 0.0));
    int status = 0;
    try {
        Pipe* pipes[2] = {outPipe.get(), errPipe.get()};
        std::string* sinks[2] = {&result.out, &result.err};
        const bool finished = readUntilClosed(pipes, sinks, limited, deadline, program) &&
                              waitUntil(pid, status, limited, deadline, program);
        if (!finished) {
            // Killed without reading on: whatever it started may still hold the pipes open.
            killChild(pid, options);
            status = waitForExit(pid, program);
            result.timedOut = true;
        }
    } catch (...) {
        killChild(pid, options);
        (void)waitForExit(pid, program);
        throw;
    }
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    return result;
}

std::string describeEnd(const ChildResult& result) {
    if (!result.started) return "could not be started";
    if (result.timedOut) return "killed at its time limit";
    if (result.signal != 0)
        return "killed by signal " + std::to_string(result.signal) + " (" +
               strsignal(result.signal) + ")";
    return "exit " + std::to_string(result.exitCode);
}

bool onPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream folders(path);
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        const std::filesystem::path candidate = std::filesystem::path(folder) / name;
        std::error_code error;
        if (std::filesystem::is_regular_file(candidate, error) &&
            access(candidate.c_str(), X_OK) == 0)
            return true;
    }
    return false;
}

std::string ownExecutable() {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error)
        throw Error("/proc/self/exe: cannot read this program's own path (" + error.message() +
                    ")");
    return self.string();
}

std::string executableBeside(const std::string& name) {
    return (std::filesystem::path(ownExecutable()).parent_path() / name).string();
}

}  // namespace onelight::world
