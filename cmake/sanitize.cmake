# GLOSSY_SANITIZE=ON builds everything of glossy's own (libraries, the glossy command, tests, benches) with
# AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer; scripts/test --sanitize uses it in a
# build folder of its own. Third-party libraries (Embree, TBB, OIIO, Ceres) stay the uninstrumented Debian
# builds: reports point into glossy's code, or into theirs only through intercepted allocations and libc.
option(GLOSSY_SANITIZE "Build with -fsanitize=address,undefined (scripts/test --sanitize)" OFF)

if(GLOSSY_SANITIZE)
  # Any UB report aborts the process so that a test cannot pass over it. GCC leaves float→int overflow
  # out of -fsanitize=undefined (clang includes it): named here so both compilers check the same set.
  set(GLOSSY_SANITIZE_FLAGS
      -fsanitize=address,undefined,float-cast-overflow
      -fno-sanitize-recover=undefined,float-cast-overflow
      -fno-omit-frame-pointer)
  add_compile_options(${GLOSSY_SANITIZE_FLAGS})
  # GCC 12's flow analysis misreads the instrumented std::regex and std::function internals and warns of
  # uninitialised members in library headers; the plain build keeps the warning for glossy's own code.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  add_link_options(${GLOSSY_SANITIZE_FLAGS})
endif()
