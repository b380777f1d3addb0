# Sanitizer and fuzzing builds (docs/decisions/sanitizers-and-fuzzing.md; scripts/sanitize drives both).
#   BOXING_SANITIZE=ON  every target built with AddressSanitizer + UndefinedBehaviorSanitizer; any report is fatal
#                       (-fno-sanitize-recover=all), so a test fails on the first one.
#   BOXING_FUZZ=ON      also the libFuzzer harnesses of tests/fuzz/ (clang only; implies BOXING_SANITIZE).
option(BOXING_SANITIZE "Build every target with ASan + UBSan, reports fatal" OFF)
option(BOXING_FUZZ "Build the libFuzzer harnesses (tests/fuzz/, clang; implies BOXING_SANITIZE)" OFF)
if(BOXING_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "BOXING_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(BOXING_SANITIZE ON CACHE BOOL "" FORCE)
endif()
if(BOXING_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # The build is what limits the sanitizer stage in CI (scripts/sanitize), and -O0 compiles in ~60% of -O1's time.
  # Targets whose tests run as fast unoptimised (control: 1 s, assets, core, the parsers, two renderer tests) are
  # built at -O0; physics, the motion graph and the fuzzed code stay at the preset's -O1 (at -O0 test_physics and
  # test_anim take 100-130 s of CPU each instead of 10-15 s).
  set(BOXING_SANITIZE_O0_TARGETS engine_control engine_render engine_platform engine_ui test_control test_assets
      test_core test_game_parsers test_render CACHE STRING "Targets built at -O0 in sanitizer builds")
  function(_boxing_sanitize_o0)
    foreach(t IN LISTS BOXING_SANITIZE_O0_TARGETS)
      if(TARGET ${t})
        target_compile_options(${t} PRIVATE -O0)
      endif()
    endforeach()
  endfunction()
  cmake_language(DEFER DIRECTORY ${CMAKE_SOURCE_DIR} CALL _boxing_sanitize_o0)  # once every target exists
endif()
