#include "bake/report/interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace onelight::bake {

namespace {

// The stage's name, copied into one of two buffers so that a handler never reads a buffer
// being written: the writer fills the idle one, then publishes its index.
struct StageName {
    char text[2][64] = {{"starting"}, {"starting"}};
    std::atomic<int> current{0};
    const char* tool = "onelight-bake";
};

StageName& stageName() {
    static StageName name;
    return name;
}

void appendText(char* out, size_t& used, size_t size, const char* text) {
    for (size_t i = 0; text[i] != '\0' && used + 1 < size; ++i) out[used++] = text[i];
}

extern "C" void onInterrupt(int signal) {
    StageName& name = stageName();
    char message[256];
    size_t used = 0;
    appendText(message, used, sizeof message, name.tool);
    appendText(
        message, used, sizeof message,
        signal == SIGINT ? ": interrupted (SIGINT) during " : ": terminated (SIGTERM) during ");
    appendText(message, used, sizeof message, name.text[name.current.load()]);
    appendText(message, used, sizeof message, "; no package was written\n");
    ssize_t ignored = ::write(STDERR_FILENO, message, used);
    (void)ignored;
    ::_exit(128 + signal);
}

}  // namespace

void installInterruptHandler(const char* tool) {
    stageName().tool = tool;
    struct sigaction action {};
    action.sa_handler = &onInterrupt;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
}

void ignoreInterrupts() {
    struct sigaction action {};
    action.sa_handler = SIG_IGN;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
}

void noteStage(const char* stage) {
    StageName& name = stageName();
    const int idle = 1 - name.current.load();
    std::strncpy(name.text[idle], stage, sizeof name.text[idle] - 1);
    name.text[idle][sizeof name.text[idle] - 1] = '\0';
    name.current.store(idle);
}

}  // namespace onelight::bake
