#pragma once
// Test-only behaviour, honoured only by raylab-import and only after its sandbox is in place,
// so tests can check what the parent makes of a helper that crashes, hangs or tries to escape.
// RAYLAB_IMPORT_TEST_CRASH names it:
//   segv     raise SIGSEGV with its default disposition, as a memory error in Assimp would
//   abort    call std::abort
//   hang     spin until killed (the parent's time limit or cancel)
//   write    open a file for writing (the filter kills the helper)
//   socket   make a network socket and connect it (likewise)
//   exec     run /bin/true (likewise)
//   garbage  answer with bytes that are not an import stream
//   exit     exit with code 66 and no answer, as a sanitizer's runtime does after its report
//   print    print on standard output and error, as some Assimp importers do, then go on
// Anything else, or the variable unset, does nothing.

namespace raylab::import {

void runTestHook();

} // namespace raylab::import
