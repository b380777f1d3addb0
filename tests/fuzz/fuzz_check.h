#pragma once
// What every harness asserts beyond "no crash, no sanitizer report": a loader that accepts an input hands back
// something the engine can use. A broken promise aborts, which libFuzzer reports (and saves) like a crash.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzz {

inline void check(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: broken promise: %s\n", what.c_str());
  std::abort();
}

template <class Matrix>
bool finite(const Matrix& m) {
  return m.allFinite();
}

}  // namespace fuzz
