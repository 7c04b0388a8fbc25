// The built polydem binary from a test: started with fork + exec, its
// stdout and stderr into a log file, and the cells of its CSV tables
// (shared by the command-line tests).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
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

// Cell `name` of every data row of a CSV (no quoted cells).
inline std::vector<std::string> column(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) header.push_back(c);
  const auto at = std::find(header.begin(), header.end(), name) - header.begin();
  std::vector<std::string> out;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    cells.resize(header.size());
    out.push_back(cells[static_cast<std::size_t>(at)]);
  }
  return out;
}

}  // namespace polydem::test
