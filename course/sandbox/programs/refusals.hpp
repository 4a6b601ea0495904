#pragma once
// Notes what a controller tried that the sandbox refuses, so that the grader can say what it was.
#include "frob/sandbox/channel.hpp"

/// From now on, a refused open() or fopen() writes its path into `header`, and system(), popen()
/// and posix_spawn() note that they start a process (their clone is refused with every signal
/// blocked, so the SIGSYS handler never runs to say so).
void noteRefusedCalls(frob::sandbox::Header* header);
