// Debian's Assimp 5.2 is built with its internal assertions on (ASSIMP_BUILD_DEBUG), and a failed
// one calls std::abort(): a truncated PLY, for one, stops the whole program inside
// aiProcess_Triangulate. Assimp reaches its assertion handler through the dynamic symbol
// Assimp::aiAssertViolation, and the header that would let us install our own handler is not
// installed, so we define that symbol here: the executable's definition takes precedence over the
// library's.
//
// In raylab-import a failed assertion ends the helper (setAssimpAssertionHandler): its text goes
// to the parent and nothing unwinds through Assimp's half-built structures. Without a handler
// (the in-process tests) it throws, and loadMesh reports the file as unreadable.

#include "io/assimp_assert.h"

#include <atomic>
#include <stdexcept>
#include <string>

namespace Assimp {

// Same signature as Assimp's declaration in <assimp/ai_assert.h> (visible there only in debug
// builds of Assimp itself).
void aiAssertViolation(const char* failedExpression, const char* file, int line);

} // namespace Assimp

namespace raylab {

namespace {
std::atomic<AssimpAssertionHandler> handler{nullptr};
} // namespace

void setAssimpAssertionHandler(AssimpAssertionHandler h) { handler.store(h); }

// Referenced by loadMesh so that the linker always takes this file out of the static library.
bool assimpAssertionsThrow() { return true; }

} // namespace raylab

void Assimp::aiAssertViolation(const char* failedExpression, const char* file, int line) {
    (void)file;
    (void)line;
    const std::string message = std::string("malformed file (Assimp internal check failed: ") +
                                (failedExpression != nullptr ? failedExpression : "?") + ")";
    if (const raylab::AssimpAssertionHandler h = raylab::handler.load(); h != nullptr) {
        h(message.c_str()); // does not return
    }
    throw std::runtime_error(message);
}
