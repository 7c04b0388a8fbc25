// The built polydem binary from a test: started with fork + exec, its
// stdout and stderr into a log file (shared by the command-line tests).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace polydem::test {

// Forks the binary with `args`, stdout/stderr to `log`; returns the pid.
inline pid_t start_binary(const std::vector<std::string>& args, const std::filesystem::path& log,
                          const char* program = POLYDEM_BINARY) {
  const pid_t pid = fork();
  if (pid == 0) {
    FILE* f = std::fopen(log.c_str(), "w");
    if (f) {
      dup2(fileno(f), STDOUT_FILENO);
      dup2(fileno(f), STDERR_FILENO);
    }
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    std::string name = program;
    argv.push_back(name.data());
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(program, argv.data());
    _exit(127);
  }
  return pid;
}

inline int exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline int run_binary(const std::vector<std::string>& args, const std::filesystem::path& log) {
  return exit_code(start_binary(args, log));
}

}  // namespace polydem::test
