#include "core/subprocess.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace prt {
namespace {

namespace fs = std::filesystem;

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

int runProgram(const std::string& program, const std::vector<std::string>& args,
               const fs::path& directory, const fs::path& logFile,
               const std::function<void(int)>& feedStdin) {
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
  ::close(report[1]);
  std::exception_ptr feedFailure;
  if (input[0] >= 0) {
    ::close(input[0]);
    // SIGPIPE ignored while feeding: a child that stops reading gives EPIPE, not our death.
    struct sigaction ignore {}, previous {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &previous);
    try {
      feedStdin(input[1]);
    } catch (...) {
      feedFailure = std::current_exception();
    }
    ::close(input[1]);
    ::sigaction(SIGPIPE, &previous, nullptr);
  }
  int childError = 0;
  ssize_t got;
  do {
    got = ::read(report[0], &childError, sizeof childError);
  } while (got < 0 && errno == EINTR);
  ::close(report[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(cannot + "waitpid: " + std::strerror(errno));
  }
  if (got == static_cast<ssize_t>(sizeof childError)) {
    throw std::runtime_error(cannot + std::strerror(childError));
  }
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
