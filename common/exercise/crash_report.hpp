#pragma once
// A crash names its place. On SIGSEGV, SIGBUS, SIGFPE, SIGILL or SIGABRT the process prints, as its
// last lines on stderr,
//   crashed (SIGSEGV: ...) in exercise 09.1, at labs/09_shadow_volumes/exercise.cpp:57 (buildAdjacency)
// ("timed out (...)" for SIGTERM, which time limits send first)
// and a few frames below it, read from the executable's debug information with addr2line (binutils,
// which every machine that builds the labs has), then dies of the same signal. The line names the
// first frame in an exercise file, where a student's mistake is, else the first frame with a source
// line. Used by every lab app and every test binary (check and the grader show that line).

namespace wb {

/// Installs the crash report for this process (idempotent).
void installCrashReport();

}  // namespace wb
