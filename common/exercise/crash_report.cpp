#include "common/exercise/crash_report.hpp"

#if defined(_WIN32)
// Windows: no signals, and no addr2line for a file:line. A crash prints its exception's line, as
// POSIX prints its signal's, and ends the process at once with the exception as its exit code: no
// error dialog (Windows Error Reporting; Wine's debugger) waiting for a click until the time limit.
#include <windows.h>

#include <cstdio>

namespace wb {
namespace {
LONG WINAPI onCrash(EXCEPTION_POINTERS* info) {
  const DWORD code = info && info->ExceptionRecord ? info->ExceptionRecord->ExceptionCode : 0;
  const char* what = code == EXCEPTION_ACCESS_VIOLATION || code == EXCEPTION_ARRAY_BOUNDS_EXCEEDED
                         ? "a bad memory access, such as an index out of range or a null pointer"
                     : code == EXCEPTION_STACK_OVERFLOW      ? "a stack overflow (a recursion without end?)"
                     : code == EXCEPTION_INT_DIVIDE_BY_ZERO  ? "an integer division by zero?"
                     : code == EXCEPTION_ILLEGAL_INSTRUCTION ? "an illegal instruction"
                                                             : "an exception nobody caught";
  std::fflush(stdout);
  std::fprintf(stderr, "crashed (exception 0x%08lX: %s); no file:line on Windows\n", static_cast<unsigned long>(code),
               what);
  std::fflush(stderr);
  return EXCEPTION_EXECUTE_HANDLER;
}
}  // namespace

void installCrashReport() {
  SetErrorMode(GetErrorMode() | SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
  SetUnhandledExceptionFilter(onCrash);
}
}  // namespace wb
#else
#include <dlfcn.h>
#include <execinfo.h>
#include <pthread.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace wb {
namespace {

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTERM};
char g_exe[4096];        // this executable's path, read at installation (not in the handler)
bool g_pie = true;       // position independent: addresses are offsets from the load base
void* g_base = nullptr;  // where this executable is loaded
bool g_installed = false;
pthread_t g_main;  // the thread that installed the report: the one running the exercises

const char* signalName(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV: a bad memory access, such as an index out of range or a null pointer";
    case SIGBUS:
      return "SIGBUS: a bad memory access";
    case SIGFPE:
      return "SIGFPE: an integer division by zero?";
    case SIGILL:
      return "SIGILL: an illegal instruction";
    case SIGTERM:
      return "stopped at its time limit: an endless loop?";
    default:
      return "SIGABRT: the program aborted (a failed assert, or an exception nobody caught)";
  }
}

// ELF header: e_type (offset 16) is 3 (ET_DYN) for a position-independent executable.
bool isPie(const char* exe) {
  unsigned char header[18] = {};
  FILE* f = std::fopen(exe, "rb");
  if (!f) return true;
  const bool read = std::fread(header, 1, sizeof header, f) == sizeof header;
  std::fclose(f);
  return !read || header[16] == 3;
}

// The addr2line command for the frames among `frames` that are in this executable (not in a
// shared library).
std::string symbolizeCommand(void* const* frames, int n) {
  // (-i: each frame's inlined calls too, innermost first; a crash inlined from a header, std::sqrt in
  // glm::normalize, is still found in the exercise that called it)
  std::string cmd = std::string("addr2line -C -f -i -e '") + g_exe + "'";
  for (int k = 0; k < n; ++k) {
    Dl_info info{};
    if (!dladdr(frames[k], &info) || info.dli_fbase != g_base) continue;
    // A return address points after its call: one byte back is the call's line.
    auto address = reinterpret_cast<uintptr_t>(frames[k]) - (k > 0 ? 1 : 0);
    if (g_pie) address -= reinterpret_cast<uintptr_t>(g_base);
    char hex[32];
    std::snprintf(hex, sizeof hex, " 0x%lx", static_cast<unsigned long>(address));
    cmd += hex;
  }
  return cmd + " 2>/dev/null";
}

// "09.1" when line `line` of `file` is in the chunk of that exercise (after its "// EXERCISE 09.1"
// marker), else "".
std::string exerciseAt(const std::string& file, int line) {
  FILE* f = std::fopen(file.c_str(), "r");
  if (!f) return "";
  std::string id;
  char text[1024];
  for (int k = 1; k <= line && std::fgets(text, sizeof text, f); ++k)
    if (const char* marker = std::strstr(text, "// EXERCISE ")) {
      id = marker + 12;
      id = id.substr(0, id.find_first_of(" :\r\n"));
    }
  std::fclose(f);
  return id;
}

// One frame of addr2line's output, as the student sees it: "labs/NN_name/exercise.cpp:57 (name)".
struct Frame {
  std::string where, function, exercise;
};

Frame readFrame(std::string function, std::string place) {
  place = place.substr(0, place.find(" (discriminator"));
  function = function.substr(0, function.find('('));
  const auto colon = place.rfind(':');
  Frame frame{place, function, ""};
  const bool exerciseFile = place.find("exercise.cpp:") != std::string::npos;  // (the student's file)
  if (colon != std::string::npos && exerciseFile)
    frame.exercise = exerciseAt(place.substr(0, colon), std::atoi(&place[colon + 1]));
  if (const auto labs = place.find("/labs/"); labs != std::string::npos) frame.where = place.substr(labs + 1);
  return frame;
}

// Prints the report from addr2line's pairs of lines (function, file:line).
void printReport(int sig, FILE* symbols) {
  Frame best;
  std::string frames;
  char function[1024], place[2048];
  int shown = 0;
  while (std::fgets(function, sizeof function, symbols) && std::fgets(place, sizeof place, symbols)) {
    function[std::strcspn(function, "\n")] = '\0';
    place[std::strcspn(place, "\n")] = '\0';
    if (std::strncmp(place, "??", 2) == 0 || std::strstr(place, "crash_report.cpp")) continue;  // (this handler)
    const Frame frame = readFrame(function, place);
    if (best.where.empty() || (!frame.exercise.empty() && best.exercise.empty())) best = frame;
    if (shown++ < 6) frames += "  at " + frame.where + " (" + frame.function + ")\n";
  }
  if (best.where.empty()) {
    std::fprintf(stderr,
                 "%s (%s); no line of the lab's own code on the stack (it was inside a library, such as the GL "
                 "driver, or the build has no debug information)\n",
                 sig == SIGTERM ? "timed out" : "crashed", signalName(sig));
    return;
  }
  const std::string in = best.exercise.empty() ? "" : " in exercise " + best.exercise + ",";
  std::fprintf(stderr, "%s%s (%s)%s at %s (%s)\n", frames.c_str(), sig == SIGTERM ? "timed out" : "crashed",
               signalName(sig), in.c_str(), best.where.c_str(), best.function.c_str());
}

void onCrash(int sig) {
  // A stop from outside (the time limit's SIGTERM) goes to any thread, often one of the GL driver's
  // own (Mesa's llvmpipe has several), whose stack holds no line of ours: hand it to the thread that
  // runs the exercises, so that the report says where that one was.
  if (sig == SIGTERM && !pthread_equal(pthread_self(), g_main) && pthread_kill(g_main, sig) == 0)
    return;                                        // (where the main thread cannot take it, this thread reports)
  for (int s : kSignals) std::signal(s, SIG_DFL);  // a second fault ends the process at once
  void* frames[48];
  const int n = backtrace(frames, 48);
  std::fflush(stdout);
  // Not async-signal-safe, but the process is ending anyway; the report is worth the risk.
  if (FILE* symbols = popen(symbolizeCommand(frames, n).c_str(), "r")) {
    printReport(sig, symbols);
    pclose(symbols);
  }
  std::fflush(stderr);
  std::raise(sig);
}

}  // namespace

void installCrashReport() {
  if (g_installed) return;
  const ssize_t length = readlink("/proc/self/exe", g_exe, sizeof g_exe - 1);
  if (length <= 0) return;
  g_exe[length] = '\0';
  g_pie = isPie(g_exe);
  Dl_info self{};
  if (!dladdr(reinterpret_cast<void*>(&installCrashReport), &self)) return;
  g_base = self.dli_fbase;
  g_main = pthread_self();
  for (int s : kSignals) std::signal(s, onCrash);
  g_installed = true;
}

}  // namespace wb
#endif
