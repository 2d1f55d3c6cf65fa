// A name unique to each test file of a unity batch (CMake's UNITY_BUILD_UNIQUE_ID, which
// tests/CMakeLists.txt sets). Test files compile eight to a translation unit, so helpers that
// two files of a folder both name in their anonymous namespaces (`render`, `error_of`, `kScene`)
// would collide, or worse, overload each other; such a file puts them in
//     namespace { namespace EYETRACE_UNITY_ID { ... } }
// which is a namespace of its own in a batch and, built file by file, anonymous again.
#pragma once

#ifndef EYETRACE_UNITY_ID
#define EYETRACE_UNITY_ID
#endif
