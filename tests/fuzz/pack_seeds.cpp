// Writes the asset pack of each scene file given (packAssets of loadSceneFile) into DIR as
// NAME.pack: the pack fuzzer's seed corpus.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/asset_pack.h"
#include "scene/scene_file.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s DIR SCENE_FILE...\n", argv[0]);
    return 2;
  }
  for (int i = 2; i < argc; ++i) {
    const std::vector<uint8_t> bytes = prt::packAssets(prt::loadSceneFile(argv[i]));
    const std::string path =
        std::string(argv[1]) + "/" + std::filesystem::path(argv[i]).stem().string() + ".pack";
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  return 0;
}
