// libFuzzer target for the scene reader: any input must either build a scene or be refused with an
// InputError (a clear message naming the key). A crash, a sanitizer report, a hang, or any other
// exception is a finding. Run by scripts/fuzz_scene.sh.
#include "scene/scene_loader.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  mrsph::SceneLimits limits;
  // The reader is under test, not the solver: small scenes keep one input well under a second even
  // with the sanitizers (a 3000-particle solid took over 10 s in its start-up power iteration on CI).
  limits.max_particles = 1000;
  try {
    mrsph::Json document;
    try {
      document = mrsph::Json::parse(text);
    } catch (const mrsph::Json::exception&) {
      return 0;  // read_scene_document turns this into an InputError (tested in the corpus)
    }
    mrsph::build_scene(document, "fuzz.json", limits);
  } catch (const mrsph::InputError&) {
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: a %s escaped instead of an InputError: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
  return 0;
}
