// What the scene fuzzer (fuzz_scene.cpp) does with one input, shared with the regression test
// that replays its findings (tests/fuzz/regressions/, test_scene.cpp). The input's first bytes
// pick the reader:
//   "unit:TEXT"            parse_quantity(TEXT) for every quantity;
//   "set:A\nB\n..."        `base_scene` loaded with the lines as --set assignments;
//   anything else          the input loaded as a scene file.
// Each reader must return or refuse the input with its own exception (SceneError, or
// std::invalid_argument from the unit parser); any other exception escapes. What is accepted must
// be usable: a finite quantity; a scene whose numbers the engine divides by finite and positive.
#pragma once

#include <string>

namespace firn::fuzz {

// "" when the input was refused cleanly or accepted and usable; else what is wrong with what was
// accepted.
std::string check_input(const std::string& input, const std::string& base_scene);

}  // namespace firn::fuzz
