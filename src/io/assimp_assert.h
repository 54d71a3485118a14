#pragma once
// What a failed Assimp assertion does (assimp_assert.cpp): by default it throws, which loadMesh
// reports; raylab-import installs a handler that sends the message to its parent and ends.

namespace raylab {

// Called with the assertion's one-line message; must not return (it ends the process).
using AssimpAssertionHandler = void (*)(const char* message);

void setAssimpAssertionHandler(AssimpAssertionHandler handler);

} // namespace raylab
