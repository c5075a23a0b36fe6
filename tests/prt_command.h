#pragma once
// Running the prt executable from end-to-end tests ($PRT_BINARY, set by CTest), and a
// per-test scratch folder that is removed afterwards.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace prt::e2e {

struct Result {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

inline std::string prtBinary() {
  const char* env = std::getenv("PRT_BINARY");
  return env ? env : "prt";
}

// Runs `prt ARGS` through the shell, capturing stdout and stderr; `environment` (such as
// "NAME=value ") prefixes the command.
inline Result run(const std::string& args, const std::string& environment = "") {
  const std::string command = environment + prtBinary() + " " + args + " 2>&1";
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// Runs `command` through the shell, capturing its stdout and stderr together.
inline Result runShell(const std::string& command) {
  Result r;
  FILE* pipe = popen(("{ " + command + "; } 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// Starts `command` under /bin/sh in a process group of its own, without waiting: the pid,
// which is also the group's (kill(-pid, SIG) signals the command and all it started), or -1.
inline pid_t spawnShellGroup(const std::string& command) {
  const pid_t child = fork();
  if (child == 0) {
    setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", command.c_str(), nullptr);
    _exit(127);
  }
  if (child > 0) setpgid(child, child);
  return child;
}

// A test fixture with a fresh scratch folder per test.
class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("prt-cli-test-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace prt::e2e
