// world/process/child_process.hpp: what runChild captures and reports, its time limit, large
// output on both streams, signals interrupting it, and the executable beside this one.
#include "world/process/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/time.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "world/error.hpp"

namespace onelight::world {
namespace {

ChildResult shell(const std::string& script, const ChildOptions& options = {}) {
    return runChild({"/bin/sh", "-c", script}, options);
}

TEST(ChildProcess, CapturesStdoutAndStderrApart) {
    const ChildResult r = shell("echo out; echo err >&2; echo more");
    EXPECT_TRUE(r.started);
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.signal, 0);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.out, "out\nmore\n");
    EXPECT_EQ(r.err, "err\n");
}

TEST(ChildProcess, MergesStderrIntoStdoutAsWritten) {
    ChildOptions options;
    options.err = ChildStream::kIntoStdout;
    const ChildResult r = shell("echo one; echo two >&2; echo three", options);
    EXPECT_EQ(r.out, "one\ntwo\nthree\n");
    EXPECT_EQ(r.err, "");
}

TEST(ChildProcess, DiscardsAStream) {
    ChildOptions options;
    options.out = ChildStream::kDiscard;
    const ChildResult r = shell("echo out; echo err >&2", options);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "err\n");
}

TEST(ChildProcess, StdinIsEmpty) {
    const ChildResult r = shell("cat; echo done");
    EXPECT_EQ(r.out, "done\n");
}

TEST(ChildProcess, ReportsTheExitCode) {
    const ChildResult r = shell("exit 3");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_EQ(r.signal, 0);
    EXPECT_EQ(describeEnd(r), "exit 3");
}

TEST(ChildProcess, ReportsTheSignalThatEndedIt) {
    const ChildResult r = shell("kill -TERM $$");
    EXPECT_EQ(r.exitCode, -1);
    EXPECT_EQ(r.signal, SIGTERM);
    EXPECT_FALSE(r.timedOut);
    EXPECT_NE(describeEnd(r).find("signal 15"), std::string::npos) << describeEnd(r);
}

TEST(ChildProcess, AMissingProgramIsReportedAsNotStarted) {
    const ChildResult r = runChild({"/nonexistent/no-such-program", "x"});
    EXPECT_FALSE(r.started);
    EXPECT_EQ(r.exitCode, 127);
    EXPECT_NE(r.err.find("/nonexistent/no-such-program: cannot run it"), std::string::npos)
        << r.err;
    // Looked up on PATH when the name has no '/'.
    const ChildResult onPathResult = runChild({"no-such-program-on-path"});
    EXPECT_FALSE(onPathResult.started);
    EXPECT_EQ(onPathResult.exitCode, 127);
    EXPECT_EQ(describeEnd(onPathResult), "could not be started");
    // Merged: the reason is in stdout's capture.
    ChildOptions merged;
    merged.err = ChildStream::kIntoStdout;
    EXPECT_NE(runChild({"no-such-program-on-path"}, merged).out.find("cannot run it"),
              std::string::npos);
}

TEST(ChildProcess, FindsProgramsOnPath) {
    EXPECT_TRUE(onPath("sh"));
    EXPECT_FALSE(onPath("no-such-program-on-path"));
    EXPECT_EQ(runChild({"sh", "-c", "echo hi"}).out, "hi\n");
}

TEST(ChildProcess, NoProgramIsAnError) {
    EXPECT_THROW((void)runChild({}), Error);
}

TEST(ChildProcess, ATimeLimitKillsItAndSaysSo) {
    ChildOptions options;
    options.timeLimitSeconds = 0.3;
    const auto start = std::chrono::steady_clock::now();
    const ChildResult r = runChild({"sleep", "30"}, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(r.timedOut);
    EXPECT_EQ(r.signal, SIGKILL);
    EXPECT_EQ(r.exitCode, -1);
    EXPECT_LT(seconds, 5.0);
    EXPECT_GE(seconds, 0.25);
    EXPECT_EQ(describeEnd(r), "killed at its time limit");
}

// Whether process `pid` still runs (neither gone nor a zombie waiting to be reaped).
bool stillRuns(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) return false;
    const size_t paren = line.rfind(')');
    return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] != 'Z';
}

TEST(ChildProcess, ATimeLimitKillsTheProcessGroup) {
    // The shell's sleep holds the pipes open; killing only the shell would leave it running.
    ChildOptions options;
    options.timeLimitSeconds = 0.3;
    options.killProcessGroup = true;
    const auto start = std::chrono::steady_clock::now();
    const ChildResult r = shell("sleep 30 & echo $!; wait", options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(r.timedOut);
    EXPECT_LT(seconds, 5.0);
    const pid_t sleeper = pid_t(std::stol(r.out));
    bool gone = false;
    for (int i = 0; i < 100 && !gone; ++i) {
        gone = !stillRuns(sleeper);
        if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_TRUE(gone) << "the shell's sleep " << sleeper << " outlived the time limit";
}

TEST(ChildProcess, AFastChildIsNotTimedOut) {
    ChildOptions options;
    options.timeLimitSeconds = 10.0;
    const ChildResult r = shell("echo quick; exit 4", options);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 4);
    EXPECT_EQ(r.out, "quick\n");
}

TEST(ChildProcess, MoreThanAPipeBufferOnBothStreamsDoesNotDeadlock) {
    // 1 MiB to each stream, stderr first: a reader of stdout alone would block the writer.
    ChildOptions options;
    options.timeLimitSeconds = 60.0;
    const ChildResult r =
        shell("head -c 1048576 /dev/zero | tr '\\0' e >&2; head -c 1048576 /dev/zero | tr '\\0' o",
              options);
    ASSERT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out.size(), 1048576u);
    EXPECT_EQ(r.err.size(), 1048576u);
    EXPECT_EQ(r.out.find_first_not_of('o'), std::string::npos);
    EXPECT_EQ(r.err.find_first_not_of('e'), std::string::npos);
}

void ignoreAlarm(int) {}

TEST(ChildProcess, SignalsInterruptingTheRunDoNotFailIt) {
    // SIGALRM every millisecond, its handler installed without SA_RESTART: every poll, read and
    // wait of the run is interrupted over and over (EINTR).
    struct sigaction alarm = {}, previous = {};
    alarm.sa_handler = ignoreAlarm;
    sigemptyset(&alarm.sa_mask);
    alarm.sa_flags = 0;
    ASSERT_EQ(sigaction(SIGALRM, &alarm, &previous), 0);
    itimerval every = {{0, 1000}, {0, 1000}}, off = {};
    ASSERT_EQ(setitimer(ITIMER_REAL, &every, nullptr), 0);
    ChildResult plain, limited;
    ChildOptions options;
    options.timeLimitSeconds = 30.0;
    try {
        plain = shell("sleep 0.2; head -c 200000 /dev/zero | tr '\\0' x; echo err >&2; exit 5");
        limited = shell("sleep 0.2; echo done", options);
    } catch (...) {
        setitimer(ITIMER_REAL, &off, nullptr);
        sigaction(SIGALRM, &previous, nullptr);
        throw;
    }
    setitimer(ITIMER_REAL, &off, nullptr);
    sigaction(SIGALRM, &previous, nullptr);
    EXPECT_EQ(plain.exitCode, 5);
    EXPECT_EQ(plain.out.size(), 200000u);
    EXPECT_EQ(plain.err, "err\n");
    EXPECT_FALSE(limited.timedOut);
    EXPECT_EQ(limited.exitCode, 0);
    EXPECT_EQ(limited.out, "done\n");
}

TEST(ChildProcess, TheExecutableBesideThisOneIsInItsFolder) {
    const std::filesystem::path self = ownExecutable();
    EXPECT_TRUE(std::filesystem::exists(self));
    EXPECT_EQ(executableBeside("onelight-bake"), (self.parent_path() / "onelight-bake").string());
}

}  // namespace
}  // namespace onelight::world
