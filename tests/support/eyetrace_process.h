// Running the built eyetrace program from a test (tests/app, tests/robustness): to completion
// through the shell, capturing its output, or as a child process that a test can signal, e.g.
// once its first checkpoint is on disk (never after a fixed sleep, so it holds on a loaded
// machine). Header-only; the tests define EYETRACE_BINARY_DIR (tests/CMakeLists.txt).
#pragma once
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

namespace eyetrace::test {

inline const std::string& eyetrace_binary() {
  static const std::string binary = EYETRACE_BINARY_DIR "/bin/eyetrace";
  return binary;
}

// One word for sh: 'it''s' quoting.
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct RunResult {
  int status = -1;     // the exit status; 128 + the signal when killed by one (the shell's way)
  std::string output;  // stdout, and stderr unless discarded
};

// Runs `eyetrace ARGS` (ARGS is shell text: quote what needs it) and waits for it.
inline RunResult run_eyetrace(const std::string& args, bool with_stderr = true) {
  RunResult r;
  if (!std::filesystem::exists(eyetrace_binary())) {
    ADD_FAILURE() << eyetrace_binary() << " is not built (build the eyetrace target first)";
    return r;
  }
  const std::string command = shell_quote(eyetrace_binary()) + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

// Starts `program` (a path, or a name looked up in PATH) with `args` (no shell), stdout and
// stderr to the file `log`, without waiting. Returns the child's pid, or -1.
inline pid_t spawn_logged(const std::string& program, const std::vector<std::string>& args, const std::string& log) {
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Starts eyetrace with `args` as spawn_logged does.
inline pid_t spawn_eyetrace(const std::vector<std::string>& args, const std::string& log) {
  return spawn_logged(eyetrace_binary(), args, log);
}

// The child's exit status, or 1000 + the signal when one killed it: unlike the shell's 128 + n,
// that tells the program's own exit(130) after a SIGINT from being killed by the SIGINT.
inline int wait_exit(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// Runs eyetrace with `args` to the end; the exit status as wait_exit gives it, or -1.
inline int run_eyetrace_logged(const std::vector<std::string>& args, const std::string& log) {
  const pid_t pid = spawn_eyetrace(args, log);
  return pid > 0 ? wait_exit(pid) : -1;
}

// Waits (up to two minutes: the machine may be busy) until `path` exists; false if the child
// exits first or time runs out.
inline bool wait_for_file(const std::string& path, pid_t pid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::filesystem::exists(path)) return true;
    int status;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

// Starts eyetrace with `args`, sends `sig` once `file` (a checkpoint's state) exists, and
// returns the exit status as wait_exit gives it; -1, with a failure showing the log, if the
// program did not start or the file never appeared.
inline int run_eyetrace_and_signal(const std::vector<std::string>& args, const std::string& log,
                                   const std::string& file, int sig) {
  if (!std::filesystem::exists(eyetrace_binary())) {
    ADD_FAILURE() << eyetrace_binary() << " is not built (build the eyetrace target first)";
    return -1;
  }
  const pid_t pid = spawn_eyetrace(args, log);
  EXPECT_GT(pid, 0);
  if (pid <= 0) return -1;
  if (!wait_for_file(file, pid)) {
    std::FILE* f = std::fopen(log.c_str(), "r");
    std::string text;
    char buffer[4096];
    while (f && std::fgets(buffer, sizeof buffer, f)) text += buffer;
    if (f) std::fclose(f);
    ADD_FAILURE() << "\"" << file << "\" never appeared; log:\n" << text;
    int status;
    if (waitpid(pid, &status, WNOHANG) == 0) {  // still running (not reaped by wait_for_file)
      kill(pid, SIGKILL);
      wait_exit(pid);
    }
    return -1;
  }
  kill(pid, sig);
  return wait_exit(pid);
}

}  // namespace eyetrace::test
