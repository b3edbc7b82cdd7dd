// libFuzzer target for what firn reads from its users (issue 20, item 4): a scene file, a value
// with a unit, and --set assignments on the shipped tire_on_snow scene (the one with every
// section). What it checks: fuzz_input.hpp. A crash, a hang, an escaped exception, a sanitizer
// report or an accepted but unusable input is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/fuzz/fuzz_input.hpp"

namespace {
std::string g_base_scene;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::ifstream in(FIRN_SOURCE_DIR "/scenes/tire_on_snow.toml");
  std::stringstream text;
  text << in.rdbuf();
  g_base_scene = text.str();
  if (g_base_scene.empty()) {
    std::fprintf(stderr, "cannot read %s/scenes/tire_on_snow.toml\n", FIRN_SOURCE_DIR);
    std::exit(1);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      firn::fuzz::check_input(std::string(reinterpret_cast<const char*>(data), size), g_base_scene);
  if (!problem.empty()) {
    std::fprintf(stderr, "accepted, but %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
