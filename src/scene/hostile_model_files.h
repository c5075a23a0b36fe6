#pragma once
// The harness of the hostile-input tests of the model readers (model_file_hostile_test.cpp,
// model_scene_hostile_test.cpp): running a read in a child process with an alarm and its memory
// measured, building hostile glTF files, and the fixture with its scratch folder. Test code only;
// the anonymous namespace gives each test file its own copy.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/input_error.h"
#include "scene/asset_pack.h"
#include "scene/model_file.h"
#include "scene/scene_file.h"

#if defined(__SANITIZE_ADDRESS__)
#define PRT_HOSTILE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PRT_HOSTILE_ASAN 1
#endif
#endif
#ifdef PRT_HOSTILE_ASAN
// From <sanitizer/allocator_interface.h>, which GCC does not install.
extern "C" size_t __sanitizer_get_current_allocated_bytes();
#else
#include <malloc.h>
#endif

namespace prt {
namespace {

namespace fs = std::filesystem;

const fs::path kSource(PRT_SOURCE_DIR);

// --- running a read in a child process -------------------------------------------------------

enum class Kind { returned, modelError, inputError, otherError, crashed, timedOut };

const char* kindName(Kind k) {
  switch (k) {
    case Kind::returned: return "returned";
    case Kind::modelError: return "ModelFileError";
    case Kind::inputError: return "InputError";
    case Kind::otherError: return "another exception";
    case Kind::crashed: return "CRASHED";
    case Kind::timedOut: return "TIMED OUT";
  }
  return "?";
}
void PrintTo(Kind k, std::ostream* os) { *os << kindName(k); }

// Bytes allocated and not freed (AddressSanitizer keeps freed blocks in quarantine, so that
// the resident size says little of what a call keeps).
size_t liveHeapBytes() {
#ifdef PRT_HOSTILE_ASAN
  return __sanitizer_get_current_allocated_bytes();
#else
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
#endif
}

// What the child reports: how the call ended, the error's message or facts about the result,
// and the warnings of a model that was read.
struct Report {
  Kind kind = Kind::crashed;
  std::string message;
  std::vector<std::string> warnings;
  long retainedKb = 0;  // heap still allocated after the call, with its result alive
};

struct Outcome : Report {
  long peakGrowthKb = 0;  // of the child's resident memory while it ran the call
  double seconds = 0;
};

std::ostream& operator<<(std::ostream& os, const Outcome& o) {
  os << kindName(o.kind) << " after " << o.seconds << " s, resident +" << o.peakGrowthKb / 1024
     << " MiB, kept " << o.retainedKb / 1024 << " MiB: " << o.message;
  for (const std::string& w : o.warnings) os << "\n  warning: " << w;
  return os;
}

long peakRssKb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

void putString(std::string& out, const std::string& s) {
  const auto n = static_cast<uint32_t>(s.size());
  out.append(reinterpret_cast<const char*>(&n), 4);
  out += s;
}
bool getString(const std::string& in, size_t& at, std::string& s) {
  uint32_t n = 0;
  if (in.size() - at < 4) return false;
  std::memcpy(&n, in.data() + at, 4);
  at += 4;
  if (in.size() - at < n) return false;
  s = in.substr(at, n);
  at += n;
  return true;
}

// Runs each of `bodies` in turn in one child process killed after `seconds` in all; under
// AddressSanitizer its reports end the child (and fail the test), elsewhere its address space
// is bounded so that a runaway allocation fails instead of exhausting the machine. Each
// outcome is sent as soon as its body returns: after a crash or a hang, the body that caused
// it is the first without one, and those after it did not run.
std::vector<Outcome> isolatedAll(const std::vector<std::function<Report()>>& bodies, int seconds = 20) {
  std::vector<Outcome> outcomes(bodies.size());
  int fds[2];
  if (pipe(fds) != 0) return outcomes;
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    alarm(static_cast<unsigned>(seconds));
#ifndef PRT_HOSTILE_ASAN
    const rlimit limit{rlim_t{6} << 30, rlim_t{6} << 30};
    setrlimit(RLIMIT_AS, &limit);
#endif
    for (const auto& body : bodies) {
      const long before = peakRssKb();
      const auto start = std::chrono::steady_clock::now();
      Report r;
      try {
        r = body();
      } catch (...) {
        r = {Kind::otherError, "an exception escaped the test's own code", {}};
      }
      const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::string record;
      record += static_cast<char>(r.kind);
      putString(record, std::to_string(peakRssKb() - before));
      putString(record, std::to_string(r.retainedKb));
      putString(record, std::to_string(took));
      putString(record, r.message);
      putString(record, std::to_string(r.warnings.size()));
      for (const std::string& w : r.warnings) putString(record, w);
      std::string out;
      putString(out, record);
      for (size_t done = 0; done < out.size();) {
        const ssize_t n = write(fds[1], out.data() + done, out.size() - done);
        if (n <= 0) _exit(3);
        done += static_cast<size_t>(n);
      }
    }
    _exit(0);
  }
  close(fds[1]);
  const auto start = std::chrono::steady_clock::now();
  std::string data;
  char buffer[4096];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    data.append(buffer, static_cast<size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  size_t done = 0, at = 0;
  for (std::string record; done < bodies.size() && getString(data, at, record); ++done) {
    Outcome& o = outcomes[done];
    size_t in = 1;
    std::string growth, retained, took, count;
    if (record.empty() || !getString(record, in, growth) || !getString(record, in, retained) ||
        !getString(record, in, took) || !getString(record, in, o.message) || !getString(record, in, count)) {
      break;
    }
    o.kind = static_cast<Kind>(record[0]);
    o.peakGrowthKb = std::stol(growth);
    o.retainedKb = std::stol(retained);
    o.seconds = std::stod(took);
    for (size_t i = 0, n = std::stoul(count); i < n; ++i) {
      std::string w;
      if (getString(record, in, w)) o.warnings.push_back(w);
    }
  }
  if (done < bodies.size()) {
    Outcome& o = outcomes[done];
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (WIFSIGNALED(status)) {
      o.kind = WTERMSIG(status) == SIGALRM ? Kind::timedOut : Kind::crashed;
      o.message = "the child ended by signal " + std::to_string(WTERMSIG(status)) +
                  (WTERMSIG(status) == SIGALRM ? " (killed after " + std::to_string(seconds) + " s)" : "");
    } else {
      o.kind = Kind::crashed;
      o.message = "the child exited with status " + std::to_string(WEXITSTATUS(status)) +
                  " without reporting (a sanitizer report above?)";
    }
    for (size_t i = done + 1; i < bodies.size(); ++i) {
      outcomes[i].kind = Kind::crashed;
      outcomes[i].message = "not run: an earlier case in its child process ended it";
    }
  }
  return outcomes;
}

Outcome isolated(const std::function<Report()>& body, int seconds = 20) {
  return isolatedAll({body}, seconds).front();
}

using Facts = std::function<std::string(const ImportedModel&)>;

std::string counts(const ImportedModel& m) {
  return "objects " + std::to_string(m.objects.size()) + ", lights " + std::to_string(m.lights.size()) +
         ", cameras " + std::to_string(m.cameras.size()) + ", textures " +
         std::to_string(m.textures.size());
}

Report readReport(const std::string& path, const ModelReadOptions& options, const Facts& facts) {
  try {
    const size_t before = liveHeapBytes();
    const ImportedModel m = readModelFile(path, options);
    const auto kept = static_cast<long>((liveHeapBytes() - before) / 1024);
    return {Kind::returned, facts ? facts(m) : counts(m), m.warnings, kept};
  } catch (const ModelFileError& e) {
    return {Kind::modelError, e.what(), {}};
  } catch (const InputError& e) {
    return {Kind::inputError, e.what(), {}};
  } catch (const std::exception& e) {
    return {Kind::otherError, std::string("std::exception: ") + e.what(), {}};
  }
}

[[maybe_unused]] Outcome readIsolated(const std::string& path, const ModelReadOptions& options = {},
                     const Facts& facts = nullptr, int seconds = 20) {
  return isolated([&] { return readReport(path, options, facts); }, seconds);
}

[[maybe_unused]] Outcome loadIsolated(const std::string& scenePath, int seconds = 20) {
  return isolated(
      [&]() -> Report {
        try {
          const Scene scene = loadSceneFile(scenePath);
          return {Kind::returned, "objects " + std::to_string(scene.objects.size()), scene.warnings};
        } catch (const InputError& e) {
          return {Kind::inputError, e.what() + std::string(" @ ") + e.where().file, {}};
        } catch (const ModelFileError& e) {
          return {Kind::modelError, e.what(), {}};
        } catch (const std::exception& e) {
          return {Kind::otherError, std::string("std::exception: ") + e.what(), {}};
        }
      },
      seconds);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}
[[maybe_unused]] bool anyContains(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& l : lines) {
    if (contains(l, part)) return true;
  }
  return false;
}

// The file was refused with a ModelFileError naming it, in bounded time and memory.
::testing::AssertionResult refused(const Outcome& o, const std::string& path) {
  std::ostringstream why;
  if (o.kind != Kind::modelError) why << "not a ModelFileError; ";
  if (!contains(o.message, path)) why << "the message does not name " << path << "; ";
  if (o.peakGrowthKb >= 256 * 1024) why << "over 256 MiB of memory; ";
  if (why.str().empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << why.str() << o;
}

// The file was read, with a warning naming it that contains `fragment`.
[[maybe_unused]] ::testing::AssertionResult readWithWarning(const Outcome& o, const std::string& path,
                                           const std::string& fragment) {
  std::ostringstream why;
  if (o.kind != Kind::returned) why << "not read; ";
  bool found = false;
  for (const std::string& w : o.warnings) found = found || (contains(w, path) && contains(w, fragment));
  if (!found) why << "no warning naming " << path << " with \"" << fragment << "\"; ";
  if (o.peakGrowthKb >= 256 * 1024) why << "over 256 MiB of memory; ";
  if (why.str().empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << why.str() << o;
}

#define EXPECT_REFUSED(outcome, path) EXPECT_TRUE(refused((outcome), (path)))
#define EXPECT_READ_WITH_WARNING(outcome, path, fragment) \
  EXPECT_TRUE(readWithWarning((outcome), (path), (fragment)))

// --- building hostile files ------------------------------------------------------------------

std::string base64(const std::string& bytes) {
  static const char* const kDigits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

template <typename T>
void append(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void putU32(std::string& s, size_t at, uint32_t v) { std::memcpy(s.data() + at, &v, 4); }

// Three float positions (36 bytes), three uint16 indices and two bytes of padding: 44 bytes.
std::string triangleBytes(float x0 = 0) {
  std::string b;
  for (const float f : {x0, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) append(b, f);
  for (const uint16_t i : std::initializer_list<uint16_t>{0, 1, 2, 0}) append(b, i);
  return b;
}
std::string dataUri(const std::string& bytes) {
  return "data:application/octet-stream;base64," + base64(bytes);
}

// The JSON arrays of a glTF file (their contents, without brackets): by default one node
// placing one mesh of one triangle whose buffer is a data: URI.
struct Gltf {
  std::string scenes = R"("scene":0,"scenes":[{"nodes":[0]}])";
  std::string nodes = R"({"mesh":0})";
  std::string meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1}]})";
  std::string accessors =
      R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
      R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"})";
  std::string bufferViews =
      R"({"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6})";
  std::string buffers = R"({"byteLength":44,"uri":")" + dataUri(triangleBytes()) + R"("})";
  std::string more;  // further top-level members, each with a leading comma

  std::string json() const {
    return R"({"asset":{"version":"2.0"},)" + scenes + R"(,"nodes":[)" + nodes +
           R"(],"meshes":[)" + meshes + R"(],"accessors":[)" + accessors +
           R"(],"bufferViews":[)" + bufferViews + R"(],"buffers":[)" + buffers + "]" + more + "}";
  }
  // A second mesh, placed by a second node: the first stays good, so the file is read and
  // what is wrong with the second shows as a warning.
  Gltf& withSecondMesh(const std::string& primitive) {
    scenes = R"("scene":0,"scenes":[{"nodes":[0,1]}])";
    nodes = R"({"mesh":0},{"mesh":1})";
    meshes += R"(,{"primitives":[)" + primitive + "]}";
    return *this;
  }
};

// A binary glTF: the 12-byte header, the JSON chunk padded with spaces and the BIN chunk
// padded with zeros (left out when `bin` is empty).
[[maybe_unused]] std::string glb(std::string json, std::string bin) {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string out = "glTF";
  append(out, uint32_t{2});
  append(out, uint32_t{0});
  append(out, static_cast<uint32_t>(json.size()));
  out += "JSON";
  out += json;
  if (!bin.empty()) {
    append(out, static_cast<uint32_t>(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
  }
  putU32(out, 8, static_cast<uint32_t>(out.size()));
  return out;
}
[[maybe_unused]] std::string glbJson() {
  Gltf g;
  g.buffers = R"({"byteLength":44})";
  return g.json();
}

uint32_t crc32(const std::string& bytes) {
  uint32_t c = 0xFFFFFFFFu;
  for (const char ch : bytes) {
    c ^= static_cast<uint8_t>(ch);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}
std::string bigEndian(uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}
std::string pngChunk(const std::string& type, const std::string& data) {
  return bigEndian(static_cast<uint32_t>(data.size())) + type + data + bigEndian(crc32(type + data));
}
// zlib around stored (uncompressed) deflate blocks.
std::string zlibStored(const std::string& raw) {
  std::string z = "\x78\x01";
  size_t at = 0;
  do {
    const size_t n = std::min<size_t>(raw.size() - at, 65535);
    z += at + n == raw.size() ? '\x01' : '\x00';
    append(z, static_cast<uint16_t>(n));
    append(z, static_cast<uint16_t>(~n));
    z += raw.substr(at, n);
    at += n;
  } while (at < raw.size());
  uint32_t a = 1, b = 0;
  for (const char ch : raw) {
    a = (a + static_cast<uint8_t>(ch)) % 65521;
    b = (b + a) % 65521;
  }
  return z + bigEndian((b << 16) | a);
}
// An RGB PNG with the size its header claims and `rows` rows of grey pixels in its IDAT
// (rows * width must stay small).
[[maybe_unused]] std::string png(uint32_t width, uint32_t height, uint32_t rows) {
  std::string ihdr = bigEndian(width) + bigEndian(height);
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, no filter, no interlace
  std::string raw;
  for (uint32_t y = 0; y < rows; ++y) raw += '\0' + std::string(3 * width, '\x80');
  return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) +
         pngChunk("IDAT", zlibStored(raw)) + pngChunk("IEND", "");
}

// A glTF file whose one material has a base colour texture: `textures`, `images` and
// `samplers` are the arrays' contents, `info` the texture info's members.
[[maybe_unused]] std::string texturedGltf(const std::string& textures, const std::string& images,
                         const std::string& samplers = "", const std::string& info = R"("index":0)") {
  Gltf g;
  g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]})";
  g.more = R"(,"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{)" + info + "}}}]";
  if (!textures.empty()) g.more += R"(,"textures":[)" + textures + "]";
  if (!images.empty()) g.more += R"(,"images":[)" + images + "]";
  if (!samplers.empty()) g.more += R"(,"samplers":[)" + samplers + "]";
  return g.json();
}

[[maybe_unused]] std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class HostileModel : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("prt-hostile-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code error;
    fs::remove_all(dir_, error);
  }

  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p.string();
  }
  std::string fifo(const std::string& name) {
    const fs::path p = dir_ / name;
    EXPECT_EQ(mkfifo(p.c_str(), 0600), 0);
    return p.string();
  }
  // A scene importing `model`, with a camera of its own.
  std::string sceneImporting(const std::string& model, const std::string& name = "import.scene") {
    return write(name, "image { width 8 height 6 output \"x.png\" }\n"
                       "camera { eye 0 0 -5 look_at 0 0 0 }\n"
                       "import { file \"" + model + "\" }\n");
  }

  fs::path dir_;
};

using HostileGltf = HostileModel;
using HostileObj = HostileModel;
using HostileScene = HostileModel;

// Reads to run later, all in one child process, each checked by its own function: the tests
// below try many variants of a file, and one process for each would cost more than the reads.
class Batch {
 public:
  void read(const std::string& path, std::function<void(const Outcome&)> check,
            const ModelReadOptions& options = {}, const Facts& facts = nullptr) {
    bodies_.push_back([path, options, facts] { return readReport(path, options, facts); });
    checks_.emplace_back(path, std::move(check));
  }
  void run(int seconds = 20) {
    const std::vector<Outcome> outcomes = isolatedAll(bodies_, seconds);
    for (size_t i = 0; i < outcomes.size(); ++i) {
      SCOPED_TRACE(checks_[i].first);
      checks_[i].second(outcomes[i]);
    }
    bodies_.clear();
    checks_.clear();
  }

 private:
  std::vector<std::function<Report()>> bodies_;
  std::vector<std::pair<std::string, std::function<void(const Outcome&)>>> checks_;
};

[[maybe_unused]] void expectRefused(const Outcome& o, const std::string& path) { EXPECT_REFUSED(o, path); }

}  // namespace
}  // namespace prt
