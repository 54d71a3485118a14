// Debian's Assimp 5.2 is built with its internal assertions on (ASSIMP_BUILD_DEBUG), and a failed
// one calls std::abort(): a truncated PLY, for one, stops the whole program inside
// aiProcess_Triangulate. Assimp reaches its assertion handler through the dynamic symbol
// Assimp::aiAssertViolation, and the header that would let us install our own handler is not
// installed, so we define that symbol here: the executable's definition takes precedence over the
// library's. It throws instead of aborting; Importer::ReadFile (and loadMesh) catch it and report
// the file as unreadable.

#include <stdexcept>
#include <string>

namespace Assimp {

// Same signature as Assimp's declaration in <assimp/ai_assert.h> (visible there only in debug
// builds of Assimp itself).
void aiAssertViolation(const char* failedExpression, const char* file, int line);

void aiAssertViolation(const char* failedExpression, const char* file, int line) {
    (void)file;
    (void)line;
    throw std::runtime_error(std::string("malformed file (Assimp internal check failed: ") +
                             (failedExpression != nullptr ? failedExpression : "?") + ")");
}

} // namespace Assimp

namespace raylab {

// Referenced by loadMesh so that the linker always takes this file out of the static library.
bool assimpAssertionsThrow() { return true; }

} // namespace raylab
