#include "core/subprocess.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace prt {
namespace {

namespace fs = std::filesystem;

// The process groups of the children running now, for killRunningPrograms (a signal handler:
// lock-free slots, 0 when free).
constexpr int kGroupSlots = 32;
std::atomic<pid_t> runningGroups[kGroupSlots];
static_assert(std::atomic<pid_t>::is_always_lock_free);

int registerGroup(pid_t group) {
  for (int i = 0; i < kGroupSlots; ++i) {
    pid_t expected = 0;
    if (runningGroups[i].compare_exchange_strong(expected, group)) return i;
  }
  return -1;  // a full table: that child is merely not ended on a signal
}

void unregisterGroup(int slot) {
  if (slot >= 0) runningGroups[slot].store(0);
}

bool isExecutable(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
}

}  // namespace

std::string findProgram(const std::string& program) {
  if (program.empty()) return "";
  if (program.find('/') != std::string::npos) return isExecutable(program) ? program : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
    if (isExecutable(candidate)) return fs::absolute(candidate).string();
  }
  return "";
}

void killRunningPrograms() {
  for (std::atomic<pid_t>& group : runningGroups) {
    const pid_t g = group.load();
    if (g > 0) ::kill(-g, SIGKILL);
  }
}

int runProgram(const std::string& program, const std::vector<std::string>& args,
               const fs::path& directory, const fs::path& logFile,
               const std::function<void(int)>& feedStdin, const ProgramWatch& watch) {
  std::vector<std::string> argvStrings = {program};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  argv.reserve(argvStrings.size() + 1);
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string cannot = "cannot run '" + program + "': ";

  // The child reports a failed exec through this pipe; a successful exec closes it.
  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    throw std::runtime_error(cannot + "pipe: " + std::strerror(errno));
  }
  int input[2] = {-1, -1};  // the child's stdin when fed
  if (feedStdin && ::pipe2(input, O_CLOEXEC) != 0) {
    const int error = errno;
    ::close(report[0]);
    ::close(report[1]);
    throw std::runtime_error(cannot + "pipe: " + std::strerror(error));
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    for (int fd : {report[0], report[1], input[0], input[1]}) {
      if (fd >= 0) ::close(fd);
    }
    throw std::runtime_error(cannot + "fork: " + std::strerror(error));
  }
  if (pid == 0) {  // child: only async-signal-safe calls from here on
    ::setpgid(0, 0);  // a group of its own, so that it can be ended whole
    ::close(report[0]);
    int error = 0;
    const int log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int devNull = input[0] >= 0 ? input[0] : ::open("/dev/null", O_RDONLY);
    if (log < 0 || devNull < 0 || ::chdir(directory.c_str()) != 0 || ::dup2(devNull, 0) < 0 ||
        ::dup2(log, 1) < 0 || ::dup2(log, 2) < 0) {
      error = errno;
    } else {
      ::execv(argv[0], argv.data());
      error = errno;
    }
    ssize_t ignored = ::write(report[1], &error, sizeof error);
    (void)ignored;
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // as the child does: whichever runs first (EACCES once it has exec'd)
  const int slot = registerGroup(pid);
  ::close(report[1]);

  // The feeding runs on a thread of its own, so that a child that stops reading cannot hold
  // this one in a write while the child is watched.
  std::exception_ptr feedFailure;
  std::thread feeder;
  struct sigaction previousPipe {};
  if (input[0] >= 0) {
    ::close(input[0]);
    // SIGPIPE ignored while feeding: a child that stops reading gives EPIPE, not our death.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &previousPipe);
    feeder = std::thread([&, fd = input[1]] {
      try {
        feedStdin(fd);
      } catch (...) {
        feedFailure = std::current_exception();
      }
      ::close(fd);
    });
  }
  int childError = 0;
  ssize_t got;
  do {
    got = ::read(report[0], &childError, sizeof childError);
  } while (got < 0 && errno == EINTR);
  ::close(report[0]);

  int status = 0;
  bool reaped = false;
  std::string ended;  // why the child was ended early ("": it was not)
  int endedBySignal = 0;
  const bool watched = watch.stallSeconds > 0 || watch.stopSignal;
  if (watched && got != static_cast<ssize_t>(sizeof childError)) {
    using Clock = std::chrono::steady_clock;
    const auto progressNow = [&] {
      std::vector<uintmax_t> seen;
      seen.push_back(watch.progress != nullptr ? watch.progress->load() : 0);
      for (const fs::path& f : watch.progressFiles) {
        std::error_code error;
        const uintmax_t size = fs::file_size(f, error);
        seen.push_back(error ? UINTMAX_MAX : size);
      }
      return seen;
    };
    std::vector<uintmax_t> last = progressNow();
    auto lastProgress = Clock::now();
    while (true) {
      const pid_t done = ::waitpid(pid, &status, WNOHANG);
      if (done == pid) {
        reaped = true;
        break;
      }
      if (done < 0 && errno != EINTR) break;  // the wait below reports it
      if (const int sig = watch.stopSignal ? watch.stopSignal() : 0) {
        endedBySignal = sig;
        ended = "'" + program + "' was ended: the run was stopped by signal " +
                std::to_string(sig);
      } else if (std::vector<uintmax_t> now = progressNow(); now != last) {
        last = std::move(now);
        lastProgress = Clock::now();
      } else if (watch.stallSeconds > 0 &&
                 std::chrono::duration<double>(Clock::now() - lastProgress).count() >
                     watch.stallSeconds) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", watch.stallSeconds);
        ended = "'" + program + "' made no progress for " + seconds +
                " s (it took no input and its output and log did not grow), so it was ended";
      }
      if (!ended.empty()) {
        ::kill(-pid, SIGKILL);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  int waitError = 0;
  if (!reaped) {
    while (::waitpid(pid, &status, 0) < 0) {
      if (errno == EINTR) continue;
      waitError = errno;
      break;
    }
  }
  // Whatever the child started and left behind (and holds its stdin open) goes with it.
  ::kill(-pid, SIGKILL);
  unregisterGroup(slot);
  if (feeder.joinable()) {
    feeder.join();
    ::sigaction(SIGPIPE, &previousPipe, nullptr);
  }
  if (got == static_cast<ssize_t>(sizeof childError)) {
    throw std::runtime_error(cannot + std::strerror(childError));
  }
  if (waitError != 0) throw std::runtime_error(cannot + "waitpid: " + std::strerror(waitError));
  if (!ended.empty()) throw ProgramEnded(ended, endedBySignal);
  if (feedFailure) std::rethrow_exception(feedFailure);
  return status;
}

std::string describeExit(int waitStatus) {
  if (WIFEXITED(waitStatus)) {
    return WEXITSTATUS(waitStatus) == 0
               ? ""
               : "exited with code " + std::to_string(WEXITSTATUS(waitStatus));
  }
  return "was killed by signal " + std::to_string(WTERMSIG(waitStatus));
}

std::string readWholeFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string lastLines(const std::string& text, int count) {
  size_t pos = text.size();
  while (pos > 0 && text[pos - 1] == '\n') --pos;
  if (pos == 0) return {};  // nothing but line ends (a program that printed nothing)
  for (int n = 0; n < count && pos > 0; ++n) {
    pos = text.rfind('\n', pos - 1);
    if (pos == std::string::npos) return text;
  }
  return text.substr(pos + 1);
}

TempDirectory::TempDirectory(const std::string& prefix) {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/" + prefix + "XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) {
    throw std::runtime_error("cannot create a temporary directory '" + pattern +
                             "': " + std::strerror(errno));
  }
  path_ = buffer.data();
}

TempDirectory::~TempDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

}  // namespace prt
