# ROOMBA_RRT_SANITIZE=ON (scripts/fuzz, a separate build directory, clang): every target is built
# with AddressSanitizer + UndefinedBehaviorSanitizer (any UB report aborts the process) and
# libFuzzer's coverage instrumentation, and cmake/fuzz.cmake adds the fuzz harnesses.
option(ROOMBA_RRT_SANITIZE "Build with ASan+UBSan and the libFuzzer harnesses (clang)" OFF)
if(ROOMBA_RRT_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ROOMBA_RRT_SANITIZE needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(RR_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all
                    -fno-omit-frame-pointer)
  # -O1: the sanitizers' usual level (readable reports, half the compile time of -O2).
  add_compile_options(${RR_SANITIZERS} -fsanitize=fuzzer-no-link -g -O1)
  add_link_options(${RR_SANITIZERS})
endif()
