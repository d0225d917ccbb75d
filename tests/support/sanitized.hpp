#pragma once
// Whether the tests run under the sanitizers (the asan preset sets TAILOR_SANITIZED=1):
// heavy loops then run fewer iterations; correctness checks still run.

#include <cstdlib>
#include <string>

namespace tailor::testing {

inline bool sanitized() {
  const char* value = std::getenv("TAILOR_SANITIZED");
  return value != nullptr && std::string(value) == "1";
}

}  // namespace tailor::testing
