// What an interrupted bake says: SIGINT or SIGTERM prints the stage that was running and that no
// package was written, then exits 128 + the signal, without running destructors (the package is
// only ever renamed into place whole, world::writeFileAtomically, so there is nothing to undo).
// The stage is the one piece of process-wide state: a signal handler can reach nothing else.
#pragma once

namespace onelight::bake {

/// Installs the handler for SIGINT and SIGTERM; `tool` starts its message ("onelight-bake").
void installInterruptHandler(const char* tool);

/// From here on SIGINT and SIGTERM are ignored: called just before the package is written, so
/// that a package renamed into place is never followed by "no package was written". Writing the
/// package, once begun, finishes.
void ignoreInterrupts();

/// Records the stage now running; `stage` must outlive the process (a string literal, or a
/// Progress's own name, which this copies).
void noteStage(const char* stage);

}  // namespace onelight::bake
