#pragma once
// Where a test finds the checkout and the build folder. Both are written at configure time into one generated file
// (build/tests/test_paths.cpp, from tests/test_paths.cpp.in) so no other test object depends on the checkout's path:
// a clone elsewhere reuses the compiled tests from ccache (scripts/ccache-env).
namespace boxing_test {
const char* source_dir();
const char* binary_dir();
}  // namespace boxing_test

#define BOXING_SOURCE_DIR (::boxing_test::source_dir())
#define BOXING_BINARY_DIR (::boxing_test::binary_dir())
