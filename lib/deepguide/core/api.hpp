#pragma once
// DEEPGUIDE_API marks what libdeepguide exports. The library is built with
// hidden visibility (lib/CMakeLists.txt): every public header opens its
// namespace as `namespace DEEPGUIDE_API deepguide {`, so what the public
// headers declare is the library's interface and the rest (helpers in .cpp
// files, the internal headers listed in lib/CMakeLists.txt) stays inside.
#define DEEPGUIDE_API [[gnu::visibility("default")]]
