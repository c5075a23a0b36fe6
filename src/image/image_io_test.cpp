#include "image/image_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/input_error.h"
#include "core/subprocess.h"
#include "image/atomic_file.h"
#include "image/srgb.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// Each test gets a fresh directory under the system temp directory, removed afterwards.
class ImageIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() /
           ("prt-image-io-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Names of everything in the test directory, sorted.
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  static std::string readBytes(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  static void writeBytes(const std::string& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
  }

  fs::path dir_;
};

// Every pixel holds the exact decoding of an 8-bit sRGB code, covering all 256 codes.
Image exactCodesImage() {
  Image image(16, 16);
  for (size_t i = 0; i < image.pixelCount(); ++i) {
    image.set(i, Color(srgb8ToLinear(static_cast<uint8_t>(i)),
                       srgb8ToLinear(static_cast<uint8_t>(255 - i)),
                       srgb8ToLinear(static_cast<uint8_t>((i * 7) % 256))));
  }
  return image;
}

Image randomImage(int width, int height, double lo, double hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  Image image(width, height);
  for (float& s : image.data()) s = static_cast<float>(dist(rng));
  return image;
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

// --- PNG ---

TEST_F(ImageIoTest, PngRoundTripKeepsExactSrgbCodes) {
  const Image image = exactCodesImage();
  writeImage(image, path("a.png"));
  EXPECT_EQ(readImage(path("a.png")), image);
}

TEST_F(ImageIoTest, PngRoundTripIsWithinOneLsb) {
  const Image image = randomImage(13, 7, -0.2, 1.2, 1);
  writeImage(image, path("a.png"));
  const Image back = readImage(path("a.png"));
  ASSERT_EQ(back.width(), 13);
  ASSERT_EQ(back.height(), 7);
  for (size_t i = 0; i < image.data().size(); ++i) {
    const double expected = std::clamp(srgbEncode(image.data()[i]), 0.0, 1.0) * 255.0;
    EXPECT_NEAR(srgbEncode(back.data()[i]) * 255.0, expected, 0.5 + 1e-6) << "sample " << i;
  }
}

TEST_F(ImageIoTest, PngIs8BitRgbWithAnSrgbChunk) {
  writeImage(Image(3, 2), path("a.png"));
  const std::string bytes = readBytes(path("a.png"));
  ASSERT_GT(bytes.size(), 33u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(bytes[24], 8);  // bit depth
  EXPECT_EQ(bytes[25], 2);  // colour type: RGB
  EXPECT_NE(bytes.find("sRGB"), std::string::npos);
}

TEST_F(ImageIoTest, PngReadsGrayAndRgba) {
  // 3x1 8-bit gray: 0, 188, 255.
  const unsigned char gray[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
      0x00, 0x3e, 0x8b, 0x4b, 0x68, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78,
      0x9c, 0x63, 0x60, 0xd8, 0xf3, 0x1f, 0x00, 0x02, 0x7b, 0x01, 0xbc, 0x86, 0xcb, 0x30,
      0x3e, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  // 2x1 8-bit RGBA: (10, 20, 30, opaque), (40, 50, 60, transparent).
  const unsigned char rgba[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
      0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4,
      0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00, 0x11, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xe0,
      0x12, 0x91, 0xfb, 0xaf, 0x61, 0x64, 0xc3, 0x00, 0x00, 0x08, 0x42, 0x01, 0xd2, 0x46, 0xb5,
      0x31, 0x13, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  writeBytes(path("gray.png"), std::string(reinterpret_cast<const char*>(gray), sizeof gray));
  writeBytes(path("rgba.png"), std::string(reinterpret_cast<const char*>(rgba), sizeof rgba));

  const Image g = readImage(path("gray.png"));
  ASSERT_EQ(g.width(), 3);
  EXPECT_EQ(g.at(0, 0), Color(0.0));
  EXPECT_EQ(g.at(1, 0), Color(static_cast<float>(srgb8ToLinear(188))));
  EXPECT_EQ(g.at(2, 0), Color(1.0));

  const Image c = readImage(path("rgba.png"));
  ASSERT_EQ(c.width(), 2);
  EXPECT_EQ(linearToSrgb8(c.at(0, 0).x), 10);
  EXPECT_EQ(linearToSrgb8(c.at(0, 0).y), 20);
  EXPECT_EQ(linearToSrgb8(c.at(0, 0).z), 30);
  EXPECT_EQ(c.at(1, 0), Color(0.0));  // transparent: composited onto black
}

TEST_F(ImageIoTest, PngBadFilesAreInputErrors) {
  writeBytes(path("text.png"), "hello, not a picture");
  EXPECT_NE(messageOf([&] { readImage(path("text.png")); }).find("not a PNG file"),
            std::string::npos);

  writeImage(randomImage(40, 40, 0, 1, 2), path("full.png"));
  const std::string bytes = readBytes(path("full.png"));
  writeBytes(path("cut.png"), bytes.substr(0, bytes.size() / 2));
  const std::string message = messageOf([&] { readImage(path("cut.png")); });
  EXPECT_NE(message.find("cut.png': invalid or truncated PNG file"), std::string::npos) << message;
}

// --- PPM ---

TEST_F(ImageIoTest, PpmRoundTripKeepsExactSrgbCodes) {
  const Image image = exactCodesImage();
  writeImage(image, path("a.ppm"));
  EXPECT_EQ(readImage(path("a.ppm")), image);
  const std::string bytes = readBytes(path("a.ppm"));
  EXPECT_EQ(bytes.substr(0, 13), "P6\n16 16\n255\n");
  EXPECT_EQ(bytes.size(), 13u + 3 * 256);
  EXPECT_EQ(static_cast<unsigned char>(bytes[13 + 3 * 200]), 200);  // R of pixel 200
}

TEST_F(ImageIoTest, PpmRoundTripIsWithinOneLsb) {
  const Image image = randomImage(5, 9, 0, 1, 3);
  writeImage(image, path("a.ppm"));
  const Image back = readImage(path("a.ppm"));
  for (size_t i = 0; i < image.data().size(); ++i) {
    EXPECT_EQ(linearToSrgb8(back.data()[i]), linearToSrgb8(image.data()[i]));
  }
}

TEST_F(ImageIoTest, PpmReadsAsciiAndSixteenBit) {
  writeBytes(path("plain.ppm"), "P3\n# a comment\n2 1\n255\n0 0 0\n255 188 1\n");
  const Image plain = readImage(path("plain.ppm"));
  ASSERT_EQ(plain.width(), 2);
  EXPECT_EQ(plain.at(0, 0), Color(0.0));
  EXPECT_EQ(linearToSrgb8(plain.at(1, 0).x), 255);
  EXPECT_EQ(linearToSrgb8(plain.at(1, 0).y), 188);
  EXPECT_EQ(linearToSrgb8(plain.at(1, 0).z), 1);

  writeBytes(path("wide.ppm"), std::string("P6 1 1 65535\n\xff\xff\x00\x00\x80\x00", 19));
  const Image wide = readImage(path("wide.ppm"));
  EXPECT_EQ(wide.at(0, 0).x, 1.0);
  EXPECT_EQ(wide.at(0, 0).y, 0.0);
  EXPECT_EQ(wide.at(0, 0).z, static_cast<float>(srgbDecode(32768.0 / 65535.0)));
}

TEST_F(ImageIoTest, PpmBadFilesAreInputErrors) {
  writeBytes(path("p5.ppm"), "P5\n1 1\n255\n\x01");
  EXPECT_NE(messageOf([&] { readImage(path("p5.ppm")); }).find("not a PPM file"),
            std::string::npos);
  writeBytes(path("short.ppm"), "P6\n2 2\n255\n\x01\x02\x03");
  EXPECT_NE(messageOf([&] {
              readImage(path("short.ppm"));
            }).find("truncated PPM file (expected 12 bytes of pixel data, found 3)"),
            std::string::npos);
  writeBytes(path("header.ppm"), "P6\n2");
  EXPECT_NE(messageOf([&] { readImage(path("header.ppm")); }).find("missing height"),
            std::string::npos);
  writeBytes(path("width.ppm"), "P6\n-2 2\n255\n");
  EXPECT_NE(messageOf([&] { readImage(path("width.ppm")); }).find("bad PPM width '-2'"),
            std::string::npos);
  writeBytes(path("huge.ppm"), "P6\n1000000000 1000000000\n255\n");
  EXPECT_NE(messageOf([&] { readImage(path("huge.ppm")); }).find("too large"), std::string::npos);
}

// --- PFM ---

TEST_F(ImageIoTest, PfmRoundTripIsBitExact) {
  Image image = randomImage(7, 5, -1e3, 1e3, 4);
  image.set(0, 0, Color(std::numeric_limits<double>::infinity(), -0.0, 1e-40));
  image.set(6, 4, Color(std::numeric_limits<double>::quiet_NaN(), 0.1, 3e38));
  writeImage(image, path("a.pfm"));
  EXPECT_EQ(readImage(path("a.pfm")), image);
}

TEST_F(ImageIoTest, PfmIsLittleEndianBottomRowFirst) {
  Image image(1, 2);
  image.set(0, 0, Color(1, 2, 3));  // top
  image.set(0, 1, Color(4, 5, 6));  // bottom
  writeImage(image, path("a.pfm"));
  const std::string bytes = readBytes(path("a.pfm"));
  const std::string header = "PF\n1 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 24);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  EXPECT_EQ(bytes.substr(header.size(), 4), std::string("\x00\x00\x80\x40", 4));  // 4.0f LE
}

TEST_F(ImageIoTest, PfmReadsGrayAndBigEndian) {
  // "Pf", positive scale = big-endian; rows bottom first: bottom 2.0f, top 0.5f.
  writeBytes(path("g.pfm"), std::string("Pf\n1 2\n1.0\n\x40\x00\x00\x00\x3f\x00\x00\x00", 19));
  const Image g = readImage(path("g.pfm"));
  ASSERT_EQ(g.height(), 2);
  EXPECT_EQ(g.at(0, 0), Color(0.5));
  EXPECT_EQ(g.at(0, 1), Color(2.0));
}

TEST_F(ImageIoTest, PfmBadFilesAreInputErrors) {
  writeBytes(path("magic.pfm"), "P6\n1 1\n255\n\x01\x02\x03");
  EXPECT_NE(messageOf([&] { readImage(path("magic.pfm")); }).find("not a PFM file"),
            std::string::npos);
  writeBytes(path("short.pfm"), "PF\n1 1\n-1.0\n\x01\x02");
  EXPECT_NE(messageOf([&] {
              readImage(path("short.pfm"));
            }).find("truncated PFM file (expected 12 bytes of pixel data, found 2)"),
            std::string::npos);
  writeBytes(path("scale.pfm"), "PF\n1 1\n0\n");
  EXPECT_NE(messageOf([&] { readImage(path("scale.pfm")); }).find("bad PFM scale"),
            std::string::npos);
}

// --- Dispatch on the extension ---

TEST_F(ImageIoTest, ExtensionsAreCaseInsensitive) {
  const Image image = exactCodesImage();
  for (const char* name : {"a.PNG", "b.Ppm", "c.pFM"}) {
    EXPECT_TRUE(isSupportedImagePath(name));
    writeImage(image, path(name));
    EXPECT_EQ(readImage(path(name)), image) << name;
  }
  EXPECT_EQ(readBytes(path("a.PNG")).substr(1, 3), "PNG");
  EXPECT_EQ(readBytes(path("b.Ppm")).substr(0, 2), "P6");
  EXPECT_EQ(readBytes(path("c.pFM")).substr(0, 2), "PF");
}

TEST_F(ImageIoTest, UnknownExtensionListsTheValidOnes) {
  EXPECT_EQ(supportedImageExtensions(),
            (std::vector<std::string>{".png", ".ppm", ".pfm", ".exr", ".jpg", ".jpeg"}));
  EXPECT_FALSE(isSupportedImagePath("out.tga"));
  EXPECT_FALSE(isSupportedImagePath("png"));
  EXPECT_FALSE(isSupportedImagePath("out.png.bak"));
  EXPECT_TRUE(isSupportedImagePath("dir.v2/out.png"));
  EXPECT_TRUE(isSupportedImagePath("out.JPG"));

  const std::string message = messageOf([&] { writeImage(Image(1, 1), path("out.tga")); });
  EXPECT_NE(message.find("'.tga'"), std::string::npos) << message;
  EXPECT_NE(message.find(".png, .ppm, .pfm, .exr, .jpg"), std::string::npos) << message;
  EXPECT_NE(messageOf([&] { writeImage(Image(1, 1), path("out")); }).find(".png, .ppm, .pfm"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { readImage(path("in.tga")); }).find(".png, .ppm, .pfm"),
            std::string::npos);
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, MissingFileCannotBeRead) {
  const std::string p = path("absent.png");
  EXPECT_EQ(messageOf([&] { readImage(p); }), "image '" + p + "' does not exist");
  const std::string fifo = path("pipe.png");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(messageOf([&] { readImage(fifo); }),
            "image '" + fifo + "' is a FIFO (named pipe), not a regular file");
  std::filesystem::remove(fifo);
}

// --- Atomic writes ---

TEST_F(ImageIoTest, WritingIntoAMissingDirectoryThrowsAndLeavesNoFile) {
  const std::string p = path("missing/x.png");
  EXPECT_EQ(messageOf([&] { writeImage(Image(2, 2), p); }),
            "cannot write '" + p + "': No such file or directory");
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, OverwriteReplacesTheFileAndLeavesNoTemporaries) {
  writeImage(Image(2, 2), path("a.pfm"));
  const Image second = randomImage(3, 1, 0, 1, 5);
  writeImage(second, path("a.pfm"));
  EXPECT_EQ(readImage(path("a.pfm")), second);
  EXPECT_EQ(listing(), std::vector<std::string>{"a.pfm"});
}

TEST_F(ImageIoTest, FailedWriteKeepsTheOldFileAndLeavesNoTemporaries) {
  const Image original = exactCodesImage();
  writeImage(original, path("a.png"));
  const std::string before = readBytes(path("a.png"));

  // The writer fails half-way through.
  EXPECT_THROW(writeFileAtomically(path("a.png"),
                                   [](std::FILE* f) {
                                     std::fputs("half an image", f);
                                     throw std::runtime_error("interrupted");
                                   }),
               std::runtime_error);
  EXPECT_EQ(readBytes(path("a.png")), before);
  EXPECT_EQ(listing(), std::vector<std::string>{"a.png"});

  // The final rename fails: the target is a (non-empty) directory.
  fs::create_directories(dir_ / "d.png" / "inside");
  const std::string message = messageOf([&] { writeImage(original, path("d.png")); });
  EXPECT_NE(message.find("cannot write '" + path("d.png") + "'"), std::string::npos) << message;
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.png", "d.png"}));
  EXPECT_TRUE(fs::is_directory(dir_ / "d.png" / "inside"));
  EXPECT_EQ(readBytes(path("a.png")), before);
}

TEST_F(ImageIoTest, ConcurrentWritersToOnePathLeaveOneCompleteImage) {
  std::vector<Image> images;
  for (unsigned i = 0; i < 8; ++i) images.push_back(randomImage(64, 64, 0, 1, 10 + i));
  std::vector<std::thread> threads;
  threads.reserve(images.size());
  for (const Image& image : images) {
    threads.emplace_back([&] {
      for (int k = 0; k < 5; ++k) writeImage(image, path("a.pfm"));
    });
  }
  for (std::thread& t : threads) t.join();
  const Image result = readImage(path("a.pfm"));
  EXPECT_NE(std::find(images.begin(), images.end(), result), images.end());
  EXPECT_EQ(listing(), std::vector<std::string>{"a.pfm"});
}

// --- OpenEXR and JPEG, written here and read back, and files another tool (ffmpeg) wrote --

TEST_F(ImageIoTest, ExrFloatKeepsEveryBitAndHalfRoundsToHalf) {
  const Image image = randomImage(37, 23, -2.0, 40.0, 7);
  writeImage(image, path("f.exr"));
  EXPECT_EQ(readImage(path("f.exr")), image);
  writeImage(image, path("h.EXR"), ImageWriteOptions{.exrHalf = true});
  const Image half = readImage(path("h.EXR"));
  ASSERT_EQ(half.width(), 37);
  for (size_t i = 0; i < image.data().size(); ++i) {
    const float v = image.data()[i];
    EXPECT_NEAR(half.data()[i], v, std::abs(v) / 1024 + 1e-4) << i;  // 11 significant bits
  }
  EXPECT_LT(fs::file_size(path("h.EXR")), fs::file_size(path("f.exr")));
}

TEST_F(ImageIoTest, JpegIsCloseToTheImageAndQualityChangesTheSize) {
  const Image image = exactCodesImage();
  writeImage(image, path("a.jpg"), ImageWriteOptions{.jpegQuality = 100});
  writeImage(image, path("b.jpeg"), ImageWriteOptions{.jpegQuality = 20});
  const Image best = readImage(path("a.jpg"));
  ASSERT_EQ(best.width(), 16);
  ASSERT_EQ(best.height(), 16);
  EXPECT_LT(fs::file_size(path("b.jpeg")), fs::file_size(path("a.jpg")));
  double error = 0;
  for (size_t p = 0; p < image.pixelCount(); ++p) {
    for (int c = 0; c < 3; ++c) {
      error += std::abs(linearToSrgb8(image.data()[3 * p + c]) -
                        linearToSrgb8(best.data()[3 * p + c]));
    }
  }
  EXPECT_LT(error / (3.0 * static_cast<double>(image.pixelCount())), 12.0) << "mean error in 8-bit codes";
}

TEST_F(ImageIoTest, DamagedExrAndJpegAreLocatedErrors) {
  writeImage(randomImage(8, 8, 0, 1, 3), path("g.exr"));
  writeImage(randomImage(8, 8, 0, 1, 3), path("g.jpg"));
  for (const char* name : {"g.exr", "g.jpg"}) {
    const std::string bytes = readBytes(path(name));
    for (const size_t keep : {size_t{0}, size_t{3}, bytes.size() / 2}) {
      const std::string cut = path(std::string("cut-") + std::to_string(keep) + name);
      writeBytes(cut, bytes.substr(0, keep));
      try {
        (void)readImage(cut);
        if (std::string(name) == "g.jpg" && keep == bytes.size() / 2) continue;  // libjpeg pads
        ADD_FAILURE() << cut << " was read";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(cut), std::string::npos) << e.what();
      }
    }
  }
}

// ffmpeg's own OpenEXR and JPEG encoders and decoders, against ours.
TEST_F(ImageIoTest, FilesFfmpegWritesAreReadAndOursAreReadByIt) {
  const std::string ffmpeg = findProgram("ffmpeg");
  if (ffmpeg.empty()) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps.sh installs it)";
  const auto convert = [&](const std::string& from, const std::vector<std::string>& options,
                           const std::string& to) {
    std::vector<std::string> args = {"-hide_banner", "-loglevel", "error", "-y", "-i", path(from)};
    args.insert(args.end(), options.begin(), options.end());
    args.push_back(path(to));
    const int status = runProgram(ffmpeg, args, dir_, path("ffmpeg.log"));
    ASSERT_EQ(describeExit(status), "") << readWholeFile(path("ffmpeg.log"));
  };
  const auto flipped = [](const Image& in) {
    Image out(in.width(), in.height());
    for (int y = 0; y < in.height(); ++y) {
      for (int x = 0; x < in.width(); ++x) out.set(x, in.height() - 1 - y, in.at(x, y));
    }
    return out;
  };
  // Orientation first, through PNG, whose rows are top first beyond doubt: a red row above a
  // blue one, written as OpenEXR by us, is red above blue once ffmpeg made it a PNG.
  Image bands(2, 2);
  bands.set(0, 0, Color(1, 0, 0));
  bands.set(1, 0, Color(1, 0, 0));
  bands.set(0, 1, Color(0, 0, 1));
  bands.set(1, 1, Color(0, 0, 1));
  writeImage(bands, path("bands.exr"));
  convert("bands.exr", {"-pix_fmt", "rgb24"}, "bands.png");
  EXPECT_EQ(readImage(path("bands.png")), bands);
  // ffmpeg 5.1 takes a PFM's first row as the top one, where the format puts the bottom
  // first: measured here, so that the bit-for-bit checks below hold whichever it does.
  writeImage(bands, path("bands.pfm"));
  convert("bands.pfm", {"-pix_fmt", "rgb24"}, "bands-pfm.png");
  const bool pfmTopFirst = readImage(path("bands-pfm.png")) == flipped(bands);

  const Image image = randomImage(24, 16, 0.0, 1.0, 11);
  writeImage(image, path("in.pfm"));
  // Theirs, float: every bit as in the PFM they came from.
  convert("in.pfm", {"-c:v", "exr", "-format", "float", "-compression", "zip16"}, "theirs.exr");
  EXPECT_EQ(readImage(path("theirs.exr")), pfmTopFirst ? flipped(image) : image);
  // Ours, read by them and written back as PFM: every bit again.
  writeImage(image, path("ours.exr"));
  convert("ours.exr", {"-c:v", "pfm", "-pix_fmt", "gbrpf32le"}, "back.pfm");
  EXPECT_EQ(readImage(path("back.pfm")), pfmTopFirst ? flipped(image) : image);
  // JPEG both ways, close to the image.
  writeImage(image, path("in.png"));
  convert("in.png", {"-q:v", "2"}, "theirs.jpg");
  writeImage(image, path("ours.jpg"));
  convert("ours.jpg", {"-pix_fmt", "rgb24"}, "back.png");
  for (const char* name : {"theirs.jpg", "back.png"}) {
    const Image read = readImage(path(name));
    ASSERT_EQ(read.width(), 24) << name;
    double error = 0;
    for (size_t i = 0; i < image.data().size(); ++i) {
      error += std::abs(linearToSrgb8(image.data()[i]) - linearToSrgb8(read.data()[i]));
    }
    // Random pixels are JPEG's worst case; a wrong decode (colours swapped, rows shifted) is
    // far worse than this.
    EXPECT_LT(error / static_cast<double>(image.data().size()), 40.0) << name;
  }
}

}  // namespace
}  // namespace prt
