// Writes the checkpoint fuzzer's seeds into DIR: checkpoints of small images as the ledger
// writes them (nothing done, a range, several runs, everything), each as the fuzzer's input
// (two bytes choosing the image, then the body after the header, without the checksum).

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "farm/checkpoint.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  struct Seed {
    const char* name;
    int width, height;
    prt::TaskSet done;
  };
  prt::TaskSet runs = prt::TaskSet::range(0, 5);
  runs.append(prt::TaskSet::range(9, 3));
  runs.append(prt::TaskSet::strided(20, 4, 3));
  const Seed seeds[] = {{"none", 8, 4, {}},
                        {"range", 8, 4, prt::TaskSet::range(3, 10)},
                        {"runs", 16, 3, runs},
                        {"all", 5, 7, prt::TaskSet::range(0, 35)}};
  for (const Seed& seed : seeds) {
    prt::CheckpointKey key;
    key.hash = 0x5052544655555a5aull;
    key.description = "fuzz";
    key.width = seed.width;
    key.height = seed.height;
    prt::Image image(seed.width, seed.height);
    std::vector<int16_t> owner(image.pixelCount(), -1);
    seed.done.forEach([&](uint64_t p) {
      image.set(p, prt::Color(0.25 * static_cast<double>(p % 4), 0.5, 1.0));
      owner[p] = static_cast<int16_t>(p % 3);
    });
    const std::string scratch = (dir / (std::string(seed.name) + ".tmp")).string();
    prt::writeCheckpoint(scratch, key, seed.done, image, owner);
    std::ifstream in(scratch, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    std::filesystem::remove(scratch);
    const size_t header = 8 + 8 + 2 + key.description.size() + 8;
    std::ofstream out(dir / (std::string(seed.name) + ".seed"), std::ios::binary);
    out.put(static_cast<char>(seed.width - 1)).put(static_cast<char>(seed.height - 1));
    out.write(bytes.data() + header, static_cast<std::streamsize>(bytes.size() - header - 8));
  }
  return 0;
}
