"""The second red team's cheats on the sandbox (issue 26), added to the synthetic class by
tests/grading/make_submissions.py. Each scores only what it earned:

  glsl_include_relative  the stubs, with the GLSL exercise file one #include of the reference by a
  glsl_include_deeper    relative name (found through the judge's shader path), by a name that climbs
  glsl_include_absolute  to / and back down, and by an absolute name: the include is refused
                         (an exercise file may include only what its stub includes), so zero
  cpp_include_copy       the stubs, with exercise.cpp including a second copy of the solutions placed
                         elsewhere on the machine (--second-copy): invisible in the sandbox, so zero
  ipc_smuggle            full, where a held-out run leaves its inputs in System V shared memory,
                         /tmp and /dev/shm, and every C++ exercise throws what a later (visible) run
                         finds there: nothing is found, so full marks, and no held-out text shown
  memory_bomb            full, with one C++ exercise touching 3 GiB: stopped at the 2 GiB limit and
                         named ("used more than 2 GiB of memory"); that exercise only is lost
  fork_bomb              full, with a runner that forks 1000 processes at start-up: stopped at the
                         process limit, and the rest of the run goes on: full marks
  glsl_endless_same      full, with an endless loop in one GLSL exercise that leaves its result as
                         it was once llvmpipe cuts the loop off: the exercise is lost (its kernel runs
                         far longer than the reference's, or its scenes time out)
  link_error             full, with a C++ exercise calling a function that is declared but never
                         defined: that exercise is lost, and the report shows the linker's
                         "undefined reference" line

And the cheats of the weakest sandbox (Gradescope's container: no namespaces), which
tests/grading/run_weak_class.sh grades with bubblewrap and unshare turned off (WB_SANDBOX_MODE=session):
  proc_snoop             full, with C++ that reads the command line and environment of every
                         process of the grading it can (grade.py and all it started) and throws what
                         holds a secret (the grader's seed, a path of the solutions or the held-out
                         tests, the judge's held-out flag): it finds none, so full marks
  results_daemon         the stubs, with a daemon (a session of its own, so a session's kill misses
                         it) that rewrites every tape and results.json it can reach for a minute: it
                         is killed when its run ends, so zero, and nothing forged is read
  supervisor_kill        full, with a runner that kills its supervisor (wb_check --runner, its parent)
                         at start-up, so that nothing joins its tape or says why it ended: grading goes
                         on, and every exercise of that lab is lost, as for a crash at start-up (every
                         runner of the lab does it), with the reason named
  fifo_tape              full, with a runner that swaps its tape for a FIFO as it exits, which would
                         stop a grader that opened it: grading goes on, and that lab's C++
                         exercises are lost (no record; the GLSL ones the judge runs itself)
"""
import re

import submission_tree as st


SMUGGLER = r"""
#include <sys/ipc.h>
#include <sys/shm.h>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
namespace {
// A held-out run (the runner is given --requests) hides what it was asked in every place another
// process might look; any other run looks there and keeps what it finds.
std::string smuggledText() {
  // Test binaries only: the runner that is given --requests hides, the others look (the lab apps a
  // runner starts share its sandbox, so they would only find what their own runner hid).
  if (std::string(program_invocation_short_name).find("_tests") == std::string::npos) return "";
  std::ifstream cl("/proc/self/cmdline");
  std::stringstream cmd;
  cmd << cl.rdbuf();
  const int id = shmget(0x57420001, 1 << 16, IPC_CREAT | 0666);
  char* shared = id >= 0 ? static_cast<char*>(shmat(id, nullptr, 0)) : nullptr;
  if (shared == reinterpret_cast<char*>(-1)) shared = nullptr;
  if (cmd.str().find("--requests") != std::string::npos) {
    std::stringstream text;
    text << std::ifstream("requests.jsonl").rdbuf();
    const std::string s = "SMUGGLED " + text.str().substr(0, 60000);
    if (shared) std::memcpy(shared, s.c_str(), s.size() + 1);
    std::ofstream("/tmp/wb_smuggled") << s;
    std::ofstream("/dev/shm/wb_smuggled") << s;
    return "";
  }
  std::stringstream found;
  if (shared && std::strncmp(shared, "SMUGGLED", 8) == 0) found << shared;
  found << std::ifstream("/tmp/wb_smuggled").rdbuf() << std::ifstream("/dev/shm/wb_smuggled").rdbuf();
  return found.str();
}
const std::string g_smuggled = smuggledText();
void throwSmuggled() {
  if (g_smuggled.find("SMUGGLED") != std::string::npos) throw std::runtime_error(g_smuggled);
}
}  // namespace
"""

FORK_BOMB = r"""
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <string>
namespace {
// In the runner (the test binary) only: 1000 children at once, each alive for a second.
const int forked = [] {
  if (std::string(program_invocation_short_name).find("_tests") == std::string::npos) return 0;
  int n = 0;
  for (int i = 0; i < 1000; ++i) {
    const pid_t pid = fork();
    if (pid == 0) {
      sleep(1);
      _exit(0);
    }
    if (pid < 0) break;
    ++n;
  }
  while (wait(nullptr) > 0) {
  }
  return n;
}();
}  // namespace
"""


def sandbox_cheats(out, full, expect, cpp, glsl, the_labs, stubs_of, second_copy, root):
    """Writes the cheats above into `out` with their expected results (see make_submissions.py for
    full, expect and stubs_of)."""
    lab, e_cpp = cpp
    glsl_lab, e_glsl = glsl
    everything = [e["id"] for _, ex in the_labs for e in ex]
    cpp_ids = [e["id"] for e in dict(the_labs)[lab] if e["file"] == e_cpp["file"]]
    reference = root / "solutions" / glsl_lab / e_glsl["file"]
    climb = "../" * 12 + str(reference).lstrip("/")
    for name, include in (("glsl_include_relative", f"../../solutions/{glsl_lab}/{e_glsl['file']}"),
                          ("glsl_include_deeper", climb), ("glsl_include_absolute", str(reference))):
        d = stubs_of(name)
        # No markers: the whole file is graded, and the whole file is the reference.
        (d / "labs" / glsl_lab / e_glsl["file"]).write_text(f'#include "{include}"\n')
        expect(name, everything)
    if second_copy:
        d = stubs_of("cpp_include_copy")
        path = d / "labs" / lab / e_cpp["file"]
        path.write_text(f'#if __has_include("{second_copy}/solutions/{lab}/{e_cpp["file"]}")\n'
                        f'#include "{second_copy}/solutions/{lab}/{e_cpp["file"]}"\n#else\n'
                        + path.read_text() + "#endif\n")
        expect("cpp_include_copy", everything)
    d = full("ipc_smuggle")
    st.prepend(d, lab, e_cpp["file"], SMUGGLER)
    for ex_id in cpp_ids:
        st.edit(d, lab, e_cpp["file"], ex_id, "  throwSmuggled();\n")
    expect("ipc_smuggle", [])
    d = full("memory_bomb")
    st.prepend(d, lab, e_cpp["file"], "#include <vector>\n")
    st.edit(d, lab, e_cpp["file"], e_cpp["id"], "  std::vector<char> bomb(size_t(3) << 30, 1);  // 3 GiB, touched\n")
    expect("memory_bomb", [e_cpp["id"]])
    st.prepend(full("fork_bomb"), lab, e_cpp["file"], FORK_BOMB)
    expect("fork_bomb", [])
    d = full("glsl_endless_same")
    # Endless in GLSL (the value stalls at 2^24); the loop guard stops it after 50000 steps, and then the
    # test is false, so the result is the reference's. The test keeps the loop from being dropped.
    text = (d / "labs" / glsl_lab / e_glsl["file"]).read_text()
    signature = text[text.index(f"// EXERCISE {e_glsl['id']}"):].split("\n", 1)[1]
    kind, param = re.search(r"\w+\s*\(\s*(?:in\s+)?(\w+)\s+(\w+)", signature).groups()
    c = param if kind == "float" else f"{param}[0][0]" if kind.startswith("mat") else f"{param}.x"
    st.edit(d, glsl_lab, e_glsl["file"], e_glsl["id"],
            f"  float wbSpin = 0.0;\n  while (wbSpin >= 0.0) wbSpin += 1.0;\n  if (wbSpin == 0.5) {c} += 1.0;\n")
    expect("glsl_endless_same", [e_glsl["id"]])
    d = full("link_error")
    st.prepend(d, lab, e_cpp["file"], "float wbDeclaredNeverDefined(float x);\n")
    st.edit(d, lab, e_cpp["file"], e_cpp["id"], "  if (wbDeclaredNeverDefined(1.0f) > 2.0f) throw 1;\n")
    expect("link_error", [e_cpp["id"]])


SNOOP = r"""
#include <dirent.h>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
namespace {
std::string readAll(const std::string& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}
// The command line and environment of every process of the grading that this one can read (the
// grader, grade.py, and all it started: its judges and their lab runs; in a container that is every
// process, and on a shared machine the others are not the grader's), and what of them holds a secret.
std::string snooped() {
  std::map<long, long> parent;
  std::map<long, std::string> cmdline;
  if (DIR* proc = opendir("/proc")) {
    while (dirent* e = readdir(proc)) {
      const long pid = std::atol(e->d_name);
      if (pid <= 0) continue;
      const std::string stat = readAll(std::string("/proc/") + e->d_name + "/stat");
      const auto close = stat.rfind(')');
      if (close == std::string::npos) continue;
      std::istringstream rest(stat.substr(close + 2));
      std::string state;
      rest >> state >> parent[pid];
      cmdline[pid] = readAll(std::string("/proc/") + e->d_name + "/cmdline");
    }
    closedir(proc);
  }
  auto graders = [&](long pid) {
    for (int depth = 0; pid > 1 && depth < 64; ++depth, pid = parent[pid])
      if (cmdline[pid].find("tools/grading/grade.py") != std::string::npos) return true;
    return false;
  };
  std::string found;
  for (const auto& [pid, line] : cmdline) {
    if (!graders(pid)) continue;
    for (const std::string& text : {line, readAll("/proc/" + std::to_string(pid) + "/environ")})
      for (const char* secret : {"WB_GRADE_SEED=", "/solutions/", "tests/hidden", "WB_HELD_OUT=1"})
        if (text.find(secret) != std::string::npos) found += text.substr(0, 300) + "\\n";
  }
  return found;
}
void throwSnooped() {
  const std::string s = snooped();
  if (!s.empty()) throw std::runtime_error("SNOOPED " + s);
}
}  // namespace
"""

RESULTS_DAEMON = r"""
#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>
#include <fstream>
#include <string>
namespace {
// A grandchild in a session of its own, which rewrites the tape it was started beside and any
// results.json it can reach, every 10 ms for a minute.
const int forged = [] {
  if (fork() != 0) return 0;
  setsid();
  if (fork() != 0) _exit(0);
  const std::string here = getcwd(nullptr, 0);
  for (int i = 0; i < 6000; ++i) {
    for (const std::string& f : {here + "/tape.jsonl", here + "/all/tape.jsonl", here + "/../results.json",
                                 std::string("/autograder/results/results.json")})
      std::ofstream(f) << "{\"score\": 100, \"forged\": true}\n";
    usleep(10000);
  }
  _exit(0);
}();
}  // namespace
"""

SUPERVISOR_KILL = r"""
#include <signal.h>
#include <unistd.h>
#include <string>
namespace {
// In the runner (the test binary) only: its parent, the supervisor that joins its tape and words why
// it ended, is killed before any test runs.
const int killedSupervisor = [] {
  if (std::string(program_invocation_short_name).find("_tests") == std::string::npos) return 0;
  return kill(getppid(), SIGKILL);
}();
}  // namespace
"""

FIFO_TAPE = r"""
#include <sys/stat.h>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
namespace {
// As the runner exits, every tape it can reach becomes a FIFO (its own, the joined one wb_check
// writes, and one where it runs): a grader or a supervisor that opened one would wait for ever.
struct SwapTape {
  ~SwapTape() {
    std::error_code ec;
    for (const auto& f : std::filesystem::recursive_directory_iterator(".", ec))
      if (f.path().filename() == "tape.jsonl") {
        std::remove(f.path().c_str());
        mkfifo(f.path().c_str(), 0666);
      }
    mkfifo("all/tape.jsonl", 0666);
  }
} swapTape;
}  // namespace
"""


def weak_sandbox_cheats(out, full, stubs_of, expect, cpp, the_labs):
    """Writes the weakest sandbox's cheats above into `out` with their expected results."""
    lab, e_cpp = cpp
    cpp_ids = [e["id"] for e in dict(the_labs)[lab] if e["file"] == e_cpp["file"]]
    everything = [e["id"] for _, ex in the_labs for e in ex]
    d = full("proc_snoop")
    st.prepend(d, lab, e_cpp["file"], SNOOP)
    st.edit(d, lab, e_cpp["file"], e_cpp["id"], "  throwSnooped();\n")
    expect("proc_snoop", [])
    st.prepend(stubs_of("results_daemon"), lab, e_cpp["file"], RESULTS_DAEMON)
    expect("results_daemon", everything)
    st.prepend(full("fifo_tape"), lab, e_cpp["file"], FIFO_TAPE)
    expect("fifo_tape", cpp_ids)
    st.prepend(full("supervisor_kill"), lab, e_cpp["file"], SUPERVISOR_KILL)
    expect("supervisor_kill", [e["id"] for e in dict(the_labs)[lab]])
