// Writes one encoded message of each kind into DIR (the message fuzzer's seed corpus), the
// scene message carrying the scene file given.

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cluster/messages.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s DIR SCENE_FILE\n", argv[0]);
    return 2;
  }
  std::ifstream scene(argv[2], std::ios::binary);
  std::stringstream text;
  text << scene.rdbuf();
  using prt::TaskSet;
  const std::vector<prt::Message> messages = {
      prt::SceneMsg{text.str(), 8, 2},
      prt::SpeedIndexMsg{0.125},
      prt::TasksMsg{TaskSet::strided(3, 40, 7)},
      prt::ResultsMsg{TaskSet::range(10, 2), {0.5f, 0.25f, 1, 0, 0.125f, 2}},
      prt::RequestMsg{},
      prt::QueryQueueMsg{},
      prt::QueueLengthMsg{17},
      prt::TransferOrderMsg{2, 64},
      prt::TransferNoticeMsg{1, TaskSet::range(100, 50)},
      prt::StopMsg{},
      prt::HeartbeatMsg{},
      prt::CheckMsg{TaskSet::strided(5, 3, 11)},
      prt::CheckResultsMsg{TaskSet::range(20, 1), {0.5f, 1e-40f, 2}},
  };
  for (size_t i = 0; i < messages.size(); ++i) {
    const prt::Bytes bytes = prt::encode(messages[i]);
    const std::string path = std::string(argv[1]) + "/" + prt::messageName(messages[i]) + ".bin";
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  return 0;
}
