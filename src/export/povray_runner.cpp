#include "export/povray_runner.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "export/pov_exporter.h"
#include "image/image_io.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// A fresh private directory under $TMPDIR (or /tmp), removed with everything in it when the
// object goes out of scope.
class TempDirectory {
 public:
  TempDirectory() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/prt-povray-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) == nullptr) {
      throw PovrayError(
          "cannot create a temporary directory '" + pattern + "': " + std::strerror(errno), "");
    }
    path_ = buffer.data();
  }
  ~TempDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

bool isExecutable(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
}

// The executable `program` names: itself if it contains a '/', else the first match on PATH;
// empty if there is none. Resolved here so that the forked child needs no PATH search.
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

std::string readWholeFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The last `count` lines of `text`: where POV-Ray says what went wrong.
std::string lastLines(const std::string& text, int count) {
  size_t pos = text.size();
  while (pos > 0 && text[pos - 1] == '\n') --pos;
  for (int n = 0; n < count && pos > 0; ++n) {
    pos = text.rfind('\n', pos - 1);
    if (pos == std::string::npos) return text;
  }
  return text.substr(pos + 1);
}

// Runs the executable at `program` (a path) with args in `directory`, stdout and stderr to
// `logFile`. Returns the wait status; throws PovrayError if the program cannot be started.
int runInDirectory(const std::string& program, const std::vector<std::string>& args,
                   const fs::path& directory, const fs::path& logFile) {
  std::vector<std::string> argvStrings = {program};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  argv.reserve(argvStrings.size() + 1);
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);

  // The child reports a failed exec through this pipe; a successful exec closes it.
  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    throw PovrayError(std::string("cannot start povray: pipe: ") + std::strerror(errno), "");
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(report[0]);
    ::close(report[1]);
    throw PovrayError(std::string("cannot start povray: fork: ") + std::strerror(error), "");
  }
  if (pid == 0) {  // child: only async-signal-safe calls from here on
    ::close(report[0]);
    int error = 0;
    const int log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int devNull = ::open("/dev/null", O_RDONLY);
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
  int childError = 0;
  ssize_t got;
  do {
    got = ::read(report[0], &childError, sizeof childError);
  } while (got < 0 && errno == EINTR);
  ::close(report[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      throw PovrayError(std::string("waiting for povray: ") + std::strerror(errno), "");
    }
  }
  if (got == static_cast<ssize_t>(sizeof childError)) {
    throw PovrayError("cannot run '" + program + "': " + std::strerror(childError), "");
  }
  return status;
}

}  // namespace

bool povrayAvailable(const std::string& program) {
  return !findProgram(program).empty();
}

Image renderWithPovray(const PovrayJob& job) {
  const std::string program = findProgram(job.program);
  if (program.empty()) {
    throw PovrayError("POV-Ray not found: no executable '" + job.program + "'" +
                          (job.program.find('/') == std::string::npos ? " on PATH" : "") +
                          "; install POV-Ray 3.7 (Debian: apt-get install povray)",
                      "");
  }
  TempDirectory dir;
  {
    std::ofstream scene(dir.path() / "scene.pov", std::ios::binary);
    scene << job.sceneText;
    scene.close();
    if (!scene) throw PovrayError("cannot write the POV-Ray scene to " + dir.path().string(), "");
  }
  PovRun run;
  run.sceneFile = "scene.pov";  // relative: POV-Ray runs in the directory
  run.imageFile = "image.png";
  run.width = job.width;
  run.height = job.height;
  run.samplesPerPixel = job.samplesPerPixel;
  run.threads = job.threads;
  const fs::path log = dir.path() / "povray.log";
  const int status = runInDirectory(program, povrayArguments(run), dir.path(), log);
  const std::string output = readWholeFile(log);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status)
                                ? "exited with code " + std::to_string(WEXITSTATUS(status))
                                : "was killed by signal " + std::to_string(WTERMSIG(status));
    throw PovrayError("povray " + how + "; its last output:\n" + lastLines(output, 15), output);
  }
  const fs::path image = dir.path() / run.imageFile;
  if (!fs::exists(image)) {
    throw PovrayError("povray wrote no image; its last output:\n" + lastLines(output, 15), output);
  }
  try {
    return readImage(image.string());
  } catch (const std::exception& e) {
    throw PovrayError(std::string("cannot read POV-Ray's image: ") + e.what(), output);
  }
}

}  // namespace prt
