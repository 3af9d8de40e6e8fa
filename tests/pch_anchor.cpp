// The one source of deepguide_test_pch: CMake compiles the test executables'
// shared precompiled header with it (tests/CMakeLists.txt).
