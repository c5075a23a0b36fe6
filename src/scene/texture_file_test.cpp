// Texture decoding against files other tools wrote, and against a PNG whose header declares
// more rows than its data can hold (found by the model reader's fuzzer: a 30 KB glTF whose
// texture made the decoder grow a 2 GB buffer).

#include "scene/texture_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace prt {
namespace {

const std::filesystem::path kSource(PRT_SOURCE_DIR);

std::vector<uint8_t> fileBytes(const std::filesystem::path& path) { return readTextureFile(path); }

// A PNG's bytes with its header's width and height both made `side` (big-endian, bytes 16-23).
std::vector<uint8_t> withSide(std::vector<uint8_t> png, uint32_t side) {
  for (size_t at : {16u, 20u}) {
    for (int k = 0; k < 4; ++k) png[at + static_cast<size_t>(k)] = static_cast<uint8_t>(side >> (24 - 8 * k));
  }
  return png;
}

TEST(TextureFile, DecodesPngsOtherToolsWroteIncludingOnesCompressedNearTheLimit) {
  for (const char* file : {"scenes/models/board-checker.png", "tests/models/blender-cube.png",
                           "tests/models/solid-2048-ffmpeg.png"}) {
    const std::vector<uint8_t> bytes = fileBytes(kSource / file);
    size_t budget = size_t{1} << 30;
    const auto image = decodeTextureImage(bytes.data(), bytes.size(), file, budget);
    ASSERT_NE(image, nullptr) << file;
    EXPECT_GT(image->width, 0) << file;
    EXPECT_EQ(image->texels.size(), static_cast<size_t>(image->width) *
                                        static_cast<size_t>(image->height) *
                                        static_cast<size_t>(image->channels))
        << file;
  }
}

TEST(TextureFile, APngThatCannotHoldTheRowsItDeclaresIsRefusedBeforeDecoding) {
  // The header now says 16,000 x 16,000 (768 MB of RGB rows, within the budget); the data is
  // still a 256 x 256 image's few kilobytes.
  const std::vector<uint8_t> bytes = withSide(fileBytes(kSource / "scenes/models/board-checker.png"), 16000);
  size_t budget = size_t{1} << 30;
  try {
    decodeTextureImage(bytes.data(), bytes.size(), "big.png", budget);
    FAIL() << "decoded";
  } catch (const TextureError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot hold them"), std::string::npos) << e.what();
  }
  EXPECT_EQ(budget, size_t{1} << 30) << "nothing taken off the budget";
}

TEST(TextureFile, APngTooLargeForTheDecoderIsRefusedByItsSize) {
  // 30,000 x 30,000: within the side limit, beyond the budget (2.5 GiB of RGB), and beyond
  // what stb reads, which then says only that no format matched.
  const std::vector<uint8_t> bytes = withSide(fileBytes(kSource / "scenes/models/board-checker.png"), 30000);
  size_t budget = size_t{1} << 30;
  try {
    decodeTextureImage(bytes.data(), bytes.size(), "huge.png", budget);
    FAIL() << "decoded";
  } catch (const TextureError& e) {
    EXPECT_NE(std::string(e.what()).find("30000 x 30000"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("budget"), std::string::npos) << e.what();
  }
}

// A PNG chunk claiming more bytes than the file has (found by the model reader's fuzzer: an
// IDAT of 1.5 GB in an 85 KB glTF, for which stb grew its buffer to 2 GB before reading).
TEST(TextureFile, APngChunkClaimingMoreThanTheFileIsRefusedBeforeDecoding) {
  const std::vector<uint8_t> good = fileBytes(kSource / "scenes/models/board-checker.png");
  // The first chunk after IHDR (at byte 33): its length made 1,560,968,458.
  std::vector<uint8_t> bytes = good;
  bytes[33] = 0x5d;
  bytes[34] = 0x0a;
  bytes[35] = 0x0a;
  bytes[36] = 0x0a;
  size_t budget = size_t{1} << 30;
  try {
    decodeTextureImage(bytes.data(), bytes.size(), "claims.png", budget);
    FAIL() << "decoded";
  } catch (const TextureError& e) {
    EXPECT_NE(std::string(e.what()).find("its pHYs chunk at byte 33 claims 1560939018 bytes"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(budget, size_t{1} << 30) << "nothing taken off the budget";
  // Cut short inside its data: the same.
  bytes.assign(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.size() / 2));
  EXPECT_THROW(decodeTextureImage(bytes.data(), bytes.size(), "half.png", budget), TextureError);
  // Bytes after IEND are not looked at.
  bytes = good;
  bytes.insert(bytes.end(), {0xff, 0xff, 0xff, 0xff, 'I', 'D', 'A', 'T'});
  EXPECT_NE(decodeTextureImage(bytes.data(), bytes.size(), "trailing.png", budget), nullptr);
}

}  // namespace
}  // namespace prt
