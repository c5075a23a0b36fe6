// libFuzzer target: the scene parser on arbitrary bytes. Bad input must end in an InputError
// (never a crash, a hang, a leak or another exception), and a scene that parses must write out
// and read back to the very same text (the promise the master's scene messages rely on).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/input_error.h"
#include "scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  prt::Scene scene;
  try {
    scene = prt::parseScene(text, "fuzz.scene");
  } catch (const prt::InputError& error) {
    // A located error must carry the file name and a line within the text.
    if (error.where().file != "fuzz.scene") std::abort();
    return 0;
  }
  const std::string written = prt::writeScene(scene);
  const std::string again = prt::writeScene(prt::parseScene(written, "written.scene"));
  if (again != written) std::abort();
  return 0;
}
