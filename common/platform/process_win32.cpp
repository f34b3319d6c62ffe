// Windows' half of process.hpp: the child in a job object of its own (its children join it, and
// nested jobs hold a test's own lab runs), stopped all at once with TerminateJobObject. Windows has
// no cap on what a process writes, so the log's size is watched instead.
#if defined(_WIN32)
#include "common/platform/process.hpp"

#include <windows.h>

#include <algorithm>
#include <cwctype>
#include <map>

namespace fs = std::filesystem;

namespace wb {
namespace {

std::wstring wide(const std::string& s) {
  if (s.empty()) return {};
  std::wstring w(size_t(MultiByteToWideChar(CP_UTF8, 0, s.data(), int(s.size()), nullptr, 0)), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, s.data(), int(s.size()), w.data(), int(w.size()));
  return w;
}

// One argument as the C runtime's parser reads it back (backslashes double only before a quote).
std::wstring quoteArgument(const std::wstring& a) {
  if (!a.empty() && a.find_first_of(L" \t\n\v\"") == std::wstring::npos) return a;
  std::wstring q = L"\"";
  for (size_t k = 0;; ++k) {
    size_t slashes = 0;
    while (k < a.size() && a[k] == L'\\') ++k, ++slashes;
    if (k == a.size()) {
      q.append(slashes * 2, L'\\');
      break;
    }
    q.append(a[k] == L'"' ? slashes * 2 + 1 : slashes, L'\\');
    q.push_back(a[k]);
  }
  return q + L"\"";
}

// Our environment with `spec.env` over it, as CreateProcessW's sorted block (names ignore case).
std::wstring environmentBlock(const ProcessSpec& spec) {
  auto lower = [](std::wstring s) {
    for (auto& c : s) c = wchar_t(std::towlower(c));
    return s;
  };
  std::map<std::wstring, std::wstring> vars;  // lower-case name -> "Name=value"
  if (wchar_t* block = GetEnvironmentStringsW()) {
    for (const wchar_t* e = block; *e; e += wcslen(e) + 1) {
      const std::wstring entry = e;
      const size_t eq = entry.find(L'=', 1);
      if (eq != std::wstring::npos) vars[lower(entry.substr(0, eq))] = entry;
    }
    FreeEnvironmentStringsW(block);
  }
  for (const auto& [name, value] : spec.env) vars[lower(wide(name))] = wide(name) + L"=" + wide(value);
  std::wstring out;
  for (const auto& kv : vars) out += kv.second + L'\0';
  return out + L'\0';
}

// A crash's exception as the signal a POSIX system would give.
int signalOf(DWORD code, std::string& detail) {
  switch (code) {
    case EXCEPTION_ACCESS_VIOLATION:
    case EXCEPTION_ARRAY_BOUNDS_EXCEEDED:
    case EXCEPTION_STACK_OVERFLOW:
    case EXCEPTION_IN_PAGE_ERROR:
      detail = "a bad memory access (an index out of range, a null pointer or a stack overflow)";
      return 11;
    case EXCEPTION_INT_DIVIDE_BY_ZERO:
      detail = "an integer division by zero";
      return 8;
    case EXCEPTION_ILLEGAL_INSTRUCTION:
      detail = "an illegal instruction";
      return 4;
    default:
      char hex[32];
      std::snprintf(hex, sizeof hex, "exception 0x%08lX", static_cast<unsigned long>(code));
      detail = hex;
      return 6;
  }
}

}  // namespace

Process::Process(const ProcessSpec& spec) : spec_(spec), started_(steadySeconds()) {
  if (spec.argv.empty()) {
    done_ = true, result_.detail = "nothing to run";
    return;
  }
  std::wstring command;
  for (const auto& a : spec.argv) command += (command.empty() ? L"" : L" ") + quoteArgument(wide(a));
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE log = INVALID_HANDLE_VALUE;
  STARTUPINFOW si{};
  si.cb = sizeof si;
  if (!spec.log.empty()) {
    log = CreateFileW(spec.log.wstring().c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                      &inherit, CREATE_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
    si.dwFlags = STARTF_USESTDHANDLES;
    si.hStdInput = GetStdHandle(STD_INPUT_HANDLE), si.hStdOutput = log, si.hStdError = log;
  }
  // A crash ends the child at once, with its exception as the exit code: no error dialog (Windows
  // Error Reporting; Wine starts its debugger) waiting for a click until the time limit. Children
  // inherit the mode, so the lab runs a test starts end the same way.
  SetErrorMode(GetErrorMode() | SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
  job_ = CreateJobObjectW(nullptr, nullptr);
  JOBOBJECT_EXTENDED_LIMIT_INFORMATION limits{};
  limits.BasicLimitInformation.LimitFlags = JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE;  // (we gone, it goes too)
  if (job_) SetInformationJobObject(job_, JobObjectExtendedLimitInformation, &limits, sizeof limits);
  std::wstring env = environmentBlock(spec);
  const std::wstring cwd = spec.cwd.empty() ? L"" : spec.cwd.wstring();
  PROCESS_INFORMATION pi{};
  const BOOL ok =
      CreateProcessW(nullptr, command.data(), nullptr, nullptr, TRUE, CREATE_SUSPENDED | CREATE_UNICODE_ENVIRONMENT,
                     env.data(), cwd.empty() ? nullptr : cwd.c_str(), &si, &pi);
  if (log != INVALID_HANDLE_VALUE) CloseHandle(log);
  if (!ok) {
    done_ = true, result_.detail = spec.argv[0] + ": cannot start it (error " + std::to_string(GetLastError()) + ")";
    return;
  }
  if (job_) AssignProcessToJobObject(job_, pi.hProcess);
  ResumeThread(pi.hThread);
  CloseHandle(pi.hThread);
  process_ = pi.hProcess, pid_ = pi.dwProcessId;
}

bool Process::reap(bool block) {
  if (WaitForSingleObject(process_, block ? INFINITE : 0) != WAIT_OBJECT_0) return false;
  DWORD code = 0;
  GetExitCodeProcess(process_, &code);
  if (job_) TerminateJobObject(job_, 1);  // (what it left running goes with it)
  CloseHandle(process_), process_ = nullptr;
  if (job_) CloseHandle(job_), job_ = nullptr;
  done_ = true;
  if (result_.end != ProcessResult::End::NotStarted) return true;
  if (code >= 0xC0000000u) {
    result_.end = ProcessResult::End::Crashed, result_.code = 128 + signalOf(code, result_.detail);
  } else {
    result_.end = ProcessResult::End::Exited, result_.code = int(code);
  }
  return true;
}

bool Process::stoppedAtWriteCap() {
  std::error_code ec;
  const auto size = fs::file_size(spec_.log, ec);
  if (spec_.maxWriteBytes <= 0 || spec_.log.empty() || ec || (long long)size <= spec_.maxWriteBytes) return false;
  stop(ProcessResult::End::WroteTooMuch);
  fs::resize_file(spec_.log, std::uintmax_t(spec_.maxWriteBytes), ec);  // (as POSIX's cap leaves it)
  return true;
}

void Process::stop(ProcessResult::End end, double) {
  if (done_) return;
  result_.end = end;
  result_.code = end == ProcessResult::End::TimedOut ? 124 : end == ProcessResult::End::WroteTooMuch ? 153 : 137;
  if (job_) TerminateJobObject(job_, UINT(result_.code));
  if (!job_) TerminateProcess(process_, UINT(result_.code));
  reap(true);
}

}  // namespace wb
#endif
