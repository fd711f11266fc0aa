#pragma once
// Running the gearbench executable from a test: its exit code, stdout and stderr; temporary
// case files; the case files of cases/; and a run interrupted at a given point of its progress.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <system_error>
#include <sys/wait.h>
#include <utility>
#include <unistd.h>
#include <vector>

#include "support/temp_dir.h"

namespace gearbench::testing_support {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code;
  std::string out;
  std::string err;
};

/// Runs gearbench; its stdout goes to `stdout_to` when given (then `out` stays empty).
inline Outcome run_gearbench(const std::string& args, const std::string& stdout_to = "") {
  const auto out_file = temp_path("run_stdout");
  const auto err_file = temp_path("run_stderr");
  const std::string command = std::string("'") + GEARBENCH_EXE + "' " + args + " >'" +
                              (stdout_to.empty() ? out_file.string() : stdout_to) + "' 2>'" + err_file.string() + "'";
  const int status = std::system(command.c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  Outcome o{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out_file), slurp(err_file)};
  fs::remove(out_file);
  fs::remove(err_file);
  return o;
}

inline std::string write_case(const std::string& name, const std::string& text) {
  const auto path = temp_path("case_" + name + ".json");
  std::ofstream(path) << text;
  return path.string();
}

/// A JSON file, parsed. It throws naming the file when it cannot be opened, which fails the
/// test clearly (parsing the unopened stream only said "unexpected end of input").
inline nlohmann::json read_json_file(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open the file " + path.string());
  return nlohmann::json::parse(in);
}

/// The directory of the repository's case files.
inline fs::path cases_dir() { return fs::path(GEARBENCH_SOURCE_DIR) / "cases"; }

/// The case file cases/`name`.json, parsed (read_json_file).
inline nlohmann::json read_case(const std::string& name) { return read_json_file(cases_dir() / (name + ".json")); }

/// Runs gearbench with `args`, sends SIGINT once its stderr shows `marker` (so the signal
/// lands in the middle of the work whatever the machine's load, not at a fixed delay), and
/// returns its exit code (−1 if it did not exit normally, −2 if the marker never came).
inline int interrupt_gearbench(const std::vector<std::string>& args, const std::string& marker) {
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) return -3;
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(GEARBENCH_EXE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::freopen("/dev/null", "w", stdout);
    ::dup2(pipe_fd[1], STDERR_FILENO);
    ::close(pipe_fd[0]);
    ::close(pipe_fd[1]);
    ::execv(GEARBENCH_EXE, argv.data());
    ::_exit(127);
  }
  ::close(pipe_fd[1]);
  std::string seen;
  char buffer[256];
  bool found = false;
  while (!found) {
    const ssize_t n = ::read(pipe_fd[0], buffer, sizeof buffer);
    if (n <= 0) break;
    seen.append(buffer, static_cast<std::size_t>(n));
    found = seen.find(marker) != std::string::npos;
  }
  if (found) ::kill(pid, SIGINT);
  while (::read(pipe_fd[0], buffer, sizeof buffer) > 0) {
  }  // drain what it says on its way out, so that it never writes into a closed pipe
  ::close(pipe_fd[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!found) return -2;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}


/// Exit 2, nothing on stdout, and on stderr one line: `error: ` and the expected text.
inline void expect_one_error_line(const Outcome& o, const std::string& expected) {
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_EQ(o.err.rfind("error: ", 0), 0u) << o.err;
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "one line: " << o.err;
  EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
  EXPECT_TRUE(o.out.empty());
}

/// Each (patch, expected) of `bad` merged into `base` (`patch` holds the members of a JSON
/// object, without braces) is refused with exit 2 and an error naming `expected`. The case
/// files are named `name`_0, `name`_1, …
inline void expect_patches_refused(const nlohmann::json& base,
                                   const std::vector<std::pair<std::string, std::string>>& bad,
                                   const std::string& name) {
  int n = 0;
  for (const auto& [patch, expected] : bad) {
    auto j = base;
    j.merge_patch(nlohmann::json::parse("{" + patch + "}"));
    const auto o = run_gearbench("run " + write_case(name + "_" + std::to_string(n++), j.dump()));
    EXPECT_EQ(o.exit_code, 2) << patch << "\n" << o.err;
    EXPECT_NE(o.err.find(expected), std::string::npos) << o.err;
  }
}

}  // namespace gearbench::testing_support
